package masl.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import masl.runtime.Mission;
import masl.runtime.scheduling.PoolScheduler;
import masl.runtime.trace.TraceEvent;
import masl.translator.MissionLoader;

/**
 * The CPU time one worker spends per agent-step of the lock-step benchmark's program
 * ({@link MaslLockStep#source}) on {@code new PoolScheduler(1)}: the figure of
 * {@code docs/performance.md} section 1 that other jobs on a shared machine disturb least. The
 * worker's thread CPU time is read at every {@value #WINDOW}th barrier trip (the trip is recorded
 * by the worker whose publication completed the step, with one worker always the same thread);
 * each window of {@value #WINDOW} steps after the first third of a mission gives a figure, and the
 * probe prints the least, the 10th percentile and the median of them all. Not a test and not part
 * of {@code gradle bench}: {@code gradle stepCpuProbe -PprobeArgs="agents steps missions"} (defaults
 * 1,000, 2,000, 12), or {@code java} with the bench's class path.
 */
final class StepCpuProbe {

    private static final int WINDOW = 50;

    private StepCpuProbe() {
    }

    public static void main(String[] args) throws Exception {
        int agents = args.length > 0 ? Integer.parseInt(args[0]) : 1_000;
        int steps = args.length > 1 ? Integer.parseInt(args[1]) : 2_000;
        int missions = args.length > 2 ? Integer.parseInt(args[2]) : 12;
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        MissionLoader program = MaslLockStep.compile(MaslLockStep.source(agents, steps));
        List<Double> windows = new ArrayList<>();
        for (int m = 0; m < missions; m++) {
            Windows mission = new Windows(threads, agents, steps / 3);
            Mission run = program.newMission()
                    .scheduler(new PoolScheduler(1))
                    .journal(new StringBuilder())
                    .trace(event -> {
                        if (event instanceof TraceEvent.BarrierTripped) {
                            mission.tripped();
                        }
                    })
                    .build();
            run.run(Duration.ofMinutes(10)).requireCompleted();
            windows.addAll(mission.figures);
        }
        Collections.sort(windows);
        if (windows.isEmpty()) {
            throw new IllegalStateException("no window of " + WINDOW + " steps was measured");
        }
        System.out.printf("agents %d, %d missions of %d steps, %d windows: ns per agent-step least %.1f, "
                + "10th percentile %.1f, median %.1f%n", agents, missions, steps, windows.size(),
                windows.get(0), windows.get(windows.size() / 10), windows.get(windows.size() / 2));
    }

    /** The windows of one mission: ns of the tripping thread's CPU per agent-step. */
    private static final class Windows {
        private final ThreadMXBean threads;
        private final int agents;
        private final int skipped;
        final List<Double> figures = new ArrayList<>();
        private int trips;
        private Thread thread;
        private long cpu;

        Windows(ThreadMXBean threads, int agents, int skipped) {
            this.threads = threads;
            this.agents = agents;
            this.skipped = skipped;
        }

        void tripped() {
            if (++trips < skipped || trips % WINDOW != 0) {
                return;
            }
            long now = threads.getCurrentThreadCpuTime();
            Thread current = Thread.currentThread();
            // A window another thread began (none with one worker) says nothing of this one's CPU.
            if (current == thread) {
                figures.add((now - cpu) / (double) (WINDOW * agents));
            }
            thread = current;
            cpu = now;
        }
    }
}
