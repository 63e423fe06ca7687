package masl.jade;

import java.time.Duration;
import java.util.List;
import java.util.Map;

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
        long deadline = System.nanoTime() + timeout.toNanos();
        List<Thread> alive = live();
        while (!alive.isEmpty()) {
            for (Thread thread : alive) {
                long leftMillis = (deadline - System.nanoTime()) / 1_000_000;
                if (leftMillis <= 0) {
                    return live();
                }
                thread.join(leftMillis);
            }
            // JADE ends some threads by starting others (a container's last act is to start one).
            alive = live();
        }
        return alive;
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
