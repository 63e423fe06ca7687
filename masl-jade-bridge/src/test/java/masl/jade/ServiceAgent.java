package masl.jade;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.locks.LockSupport;
import masl.runtime.testing.TestAgent;

/** An agent type with primitives for FIPA agents to invoke: results, exceptions, and a release. */
public class ServiceAgent extends TestAgent {

    /** The one call of {@link #gated()} a test holds open; a test sets a fresh one before its mission. */
    public record Gate(CompletableFuture<Void> entered, CompletableFuture<Integer> result) {
        public Gate() {
            this(new CompletableFuture<>(), new CompletableFuture<>());
        }
    }

    public static volatile Gate gate = new Gate();

    /** Others may read it (QUERY_REF). */
    public int battery = 80;
    /** Others may not read it. */
    public String secret = "hidden";

    private final CompletableFuture<Void> released = new CompletableFuture<>();

    public int add(int a, int b) {
        return a + b;
    }

    public int divide(int a, int b) {
        return a / b;
    }

    /** A result that cannot be written as JSON: its {@code toString} throws. */
    public Object unwritable() {
        return new Object() {
            @Override
            public String toString() {
                throw new IllegalStateException("no text for this");
            }
        };
    }

    /** Never returns: a call in progress when the body's JVM is killed. */
    public int hang() {
        while (true) {
            LockSupport.park(this);
        }
    }

    /**
     * Tells the test it has started ({@link Gate#entered}) and returns what the test gives
     * ({@link Gate#result}): a call the test holds open. Its body must be in the test's JVM.
     */
    public int gated() throws InterruptedException, ExecutionException {
        Gate current = gate;
        current.entered().complete(null);
        return current.result().get();
    }

    /** Lets the agent's program ({@link TestPrograms.UntilReleased}) finish. */
    public void release() {
        released.complete(null);
    }

    /** Completed by {@link #release()}. */
    CompletableFuture<Void> released() {
        return released;
    }
}
