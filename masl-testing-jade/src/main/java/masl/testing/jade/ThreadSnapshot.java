package masl.testing.jade;

import java.time.Duration;
import java.util.List;
import java.util.Set;
import masl.jade.platform.JadeThreads;

/**
 * The threads alive at one moment, to tell which threads a test started and left behind: those alive
 * later that were not alive then. The JVM's own threads (outside the {@code main} thread group:
 * reference handling, process reapers, an attach listener), the common fork-join pool's and JUnit's
 * ({@code junit-…}) are never counted: they are shared by the whole JVM, not a test's to end.
 */
public final class ThreadSnapshot {

    private final Set<Thread> alive;
    private final ThreadGroup applicationGroup;

    private ThreadSnapshot(Set<Thread> alive, ThreadGroup applicationGroup) {
        this.alive = alive;
        this.applicationGroup = applicationGroup;
    }

    /** The threads alive now. */
    public static ThreadSnapshot take() {
        return new ThreadSnapshot(Set.copyOf(Thread.getAllStackTraces().keySet()), mainGroup());
    }

    /** The threads alive now that were not alive at the snapshot, but the JVM's, JUnit's and the common pool's. */
    public List<Thread> startedSince() {
        return Thread.getAllStackTraces().keySet().stream()
                .filter(thread -> thread.isAlive() && !alive.contains(thread) && countsAsStarted(thread))
                .toList();
    }

    /**
     * Waits until every thread started since the snapshot has ended, or {@code timeout} elapsed.
     *
     * @return those still alive: empty when all have ended
     * @throws InterruptedException if the calling thread is interrupted while waiting
     */
    public List<Thread> awaitStartedEnded(Duration timeout) throws InterruptedException {
        return JadeThreads.awaitEnded(this::startedSince, timeout);
    }

    /**
     * A thread as a failure message names it: its name and the innermost frame of its stack that is
     * not the JDK's (the code that waits there, rather than the JDK's {@code park} or {@code wait}).
     */
    public static String describe(Thread thread) {
        StackTraceElement[] stack = thread.getStackTrace();
        for (StackTraceElement frame : stack) {
            String className = frame.getClassName();
            if (!className.startsWith("java.") && !className.startsWith("jdk.") && !className.startsWith("sun.")) {
                return thread.getName() + " at " + frame;
            }
        }
        return stack.length == 0 ? thread.getName() : thread.getName() + " at " + stack[0];
    }

    private boolean countsAsStarted(Thread thread) {
        String name = thread.getName();
        return inApplicationGroup(thread) && !name.startsWith("junit-")
                && !name.startsWith("ForkJoinPool.commonPool-worker-");
    }

    private boolean inApplicationGroup(Thread thread) {
        for (ThreadGroup group = thread.getThreadGroup(); group != null; group = group.getParent()) {
            if (group == applicationGroup) {
                return true;
            }
        }
        return false;
    }

    /** The thread group of the JVM's main thread, ancestor of every group an application makes. */
    private static ThreadGroup mainGroup() {
        ThreadGroup group = Thread.currentThread().getThreadGroup();
        while (group.getParent() != null && group.getParent().getParent() != null) {
            group = group.getParent();
        }
        return group;
    }
}
