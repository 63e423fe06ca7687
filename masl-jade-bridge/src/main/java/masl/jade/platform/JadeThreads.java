package masl.jade.platform;

import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;

/**
 * The threads of this JVM that run JADE's code: agents' threads, threaded behaviours, message
 * deliverers, the intra-platform server and its tickers, JADE's timer. A thread is JADE's when the
 * outermost frame of its stack that is not the JDK's belongs to a {@code jade.} class.
 */
public final class JadeThreads {

    private JadeThreads() {
    }

    /** The live threads running JADE's code now. */
    public static List<Thread> live() {
        return Thread.getAllStackTraces().entrySet().stream()
                .filter(entry -> entry.getKey().isAlive() && runsJade(entry.getValue()))
                .map(Map.Entry::getKey)
                .toList();
    }

    /**
     * Waits until no JADE thread is alive, or {@code timeout} elapsed.
     *
     * @return the JADE threads still alive: empty when all have ended
     * @throws InterruptedException if the calling thread is interrupted while waiting
     */
    public static List<Thread> awaitNone(Duration timeout) throws InterruptedException {
        return awaitEnded(JadeThreads::live, timeout);
    }

    /**
     * Waits until {@code alive} names no thread, or {@code timeout} elapsed: joins the threads it
     * names, then asks it again, since a thread may start another as its last act (JADE ends some
     * threads so: a container's last act is to start one).
     *
     * @return the threads {@code alive} still names: empty when all have ended
     * @throws InterruptedException if the calling thread is interrupted while waiting
     */
    public static List<Thread> awaitEnded(Supplier<List<Thread>> alive, Duration timeout) throws InterruptedException {
        long deadline = System.nanoTime() + timeout.toNanos();
        List<Thread> threads = alive.get();
        while (!threads.isEmpty()) {
            for (Thread thread : threads) {
                long leftMillis = (deadline - System.nanoTime()) / 1_000_000;
                if (leftMillis <= 0) {
                    return alive.get();
                }
                thread.join(leftMillis);
            }
            threads = alive.get();
        }
        return threads;
    }

    private static boolean runsJade(StackTraceElement[] stack) {
        for (int i = stack.length - 1; i >= 0; i--) {
            String className = stack[i].getClassName();
            if (!className.startsWith("java.") && !className.startsWith("jdk.")
                    && !className.startsWith("sun.")) {
                return className.startsWith("jade.");
            }
        }
        return false;
    }
}
