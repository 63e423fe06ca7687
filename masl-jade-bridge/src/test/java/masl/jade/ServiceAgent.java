package masl.jade;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.locks.LockSupport;
import masl.runtime.testing.TestAgent;

/** An agent type with primitives for FIPA agents to invoke: results, exceptions, and a release. */
public class ServiceAgent extends TestAgent {

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

    /** Lets the agent's program ({@link TestPrograms.UntilReleased}) finish. */
    public void release() {
        released.complete(null);
    }

    /** Completed by {@link #release()}. */
    CompletableFuture<Void> released() {
        return released;
    }
}
