package masl.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryMXBean;
import java.time.Duration;
import java.util.Locale;
import masl.runtime.Mission;
import masl.runtime.scheduling.PoolScheduler;
import masl.runtime.trace.TraceEvent;
import masl.translator.MissionLoader;

/**
 * A mission of 100,000 agents in one synchronous block, in a fresh JVM with the
 * default heap, started as the command starts its JVM ({@link ColdTranslation#runFresh}). {@link
 * #main} is that JVM: it prints the time to start (the program's source to the end of its first step:
 * translating, javac, creating the agents, the first wave), the steps per second of the first
 * {@value #FIRST_STEPS} steps and of the steps after them, and the bytes per agent (heap in use after
 * a collection at the end of the first step, less before, divided by N). The fresh JVM is still
 * compiling the runtime during the first steps: a long mission steps at the second rate.
 */
final class AgentScale {

    /**
     * Start, steps per second and bytes per agent of one fresh JVM; and the processor time the start
     * took (all of the JVM's threads), which other jobs on the machine lengthen much less than the start.
     */
    record Figures(double startSeconds, double stepsPerSecond, double laterStepsPerSecond, double bytesPerAgent,
            double startCpuSeconds) { }

    /** The steps of the first rate; the second is that of the steps after them. */
    static final int FIRST_STEPS = 200;

    private AgentScale() {
    }

    public static void main(String[] args) throws Exception {
        int agents = Integer.parseInt(args[0]);
        int steps = Integer.parseInt(args[1]);
        MemoryMXBean memory = ManagementFactory.getMemoryMXBean();
        String source = MaslLockStep.source(agents, steps);
        System.gc();
        long heapBefore = memory.getHeapMemoryUsage().getUsed();
        long start = System.nanoTime();
        long cpuStart = Bench.processCpuNanos();
        long[] firstStep = new long[1];
        long[] cpuFirstStep = new long[1];
        long[] heapStarted = new long[1];
        StepClock clock = new StepClock();
        StepClock later = new StepClock();
        int[] stepsEnded = new int[1];
        MissionLoader program = MaslLockStep.compile(source);
        Mission mission = program.newMission().scheduler(new PoolScheduler()).journal(new StringBuilder())
                .trace(event -> {
                    if (event instanceof TraceEvent.BarrierTripped) {
                        // The FIRST_STEPS-th step ends both: the first rate's last, the second's start.
                        if (++stepsEnded[0] <= FIRST_STEPS) {
                            clock.stepEnded();
                        }
                        if (stepsEnded[0] >= FIRST_STEPS) {
                            later.stepEnded();
                        }
                        if (firstStep[0] == 0) {
                            firstStep[0] = System.nanoTime();
                            cpuFirstStep[0] = Bench.processCpuNanos();
                            // Started: every agent exists and has run its first step. Delays the second step
                            // by a collection, a small part of the steps the rate is taken over.
                            System.gc();
                            heapStarted[0] = memory.getHeapMemoryUsage().getUsed();
                        }
                    }
                }).build();
        mission.run(Duration.ofMinutes(30)).requireCompleted();
        System.out.printf(Locale.ROOT, "%f %f %f %f %f%n", (firstStep[0] - start) / 1e9, clock.stepsPerSecond(),
                later.stepsPerSecond(), (double) (heapStarted[0] - heapBefore) / agents, (cpuFirstStep[0] - cpuStart) / 1e9);
    }

    static Figures measure(int agents, int steps) throws Exception {
        String output = ColdTranslation.runFresh(AgentScale.class, String.valueOf(agents), String.valueOf(steps));
        String[] figures = output.substring(output.lastIndexOf('\n') + 1).split(" ");
        return new Figures(Double.parseDouble(figures[0]), Double.parseDouble(figures[1]), Double.parseDouble(figures[2]),
                Double.parseDouble(figures[3]), Double.parseDouble(figures[4]));
    }
}
