package masl.runtime.scheduling;

import java.util.concurrent.Callable;
import java.util.concurrent.ForkJoinPool;
import masl.runtime.AgentContext;

/**
 * Runs a call that really blocks its thread (a robot API, {@code Thread.sleep} inside a
 * primitive) so that the agents' pool stays live: on a {@link ForkJoinPool} worker the pool adds
 * a compensating worker for the duration of the call ({@link ForkJoinPool#managedBlock}), and a
 * {@link PoolScheduler} lets another of its runners use it; on any
 * other thread the call simply runs. Primitives implemented in Java use it for their blocking
 * parts; statements the translator can see ({@code .sleep(ms)}) suspend instead, see
 * {@link AgentContext#sleep}.
 */
public final class Blocking {

    private Blocking() {
    }

    /** Runs {@code call}, which may block, and returns its result. */
    public static <V> V call(Callable<V> call) throws Exception {
        BlockingCall<V> blocker = new BlockingCall<>(call);
        PoolScheduler.blocking(true);
        try {
            ForkJoinPool.managedBlock(blocker);
        } finally {
            PoolScheduler.blocking(false);
        }
        return blocker.result();
    }

    /** Sleeps {@code ms} milliseconds without starving the pool. */
    public static void sleep(long ms) throws InterruptedException {
        try {
            call(() -> {
                Thread.sleep(ms);
                return null;
            });
        } catch (InterruptedException | RuntimeException e) {
            throw e;
        } catch (Exception impossible) {
            throw new IllegalStateException(impossible);
        }
    }

    private static final class BlockingCall<V> implements ForkJoinPool.ManagedBlocker {
        private final Callable<V> call;
        private boolean done;
        private V value;
        private Exception failure;

        BlockingCall(Callable<V> call) {
            this.call = call;
        }

        @Override
        public boolean block() {
            try {
                value = call.call();
            } catch (Exception e) {
                failure = e;
            }
            done = true;
            return true;
        }

        @Override
        public boolean isReleasable() {
            return done;
        }

        V result() throws Exception {
            if (failure != null) {
                throw failure;
            }
            return value;
        }
    }
}
