package masl.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.time.Duration;
import java.util.Locale;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import masl.runtime.AgentContext;
import masl.runtime.AgentImplementation;
import masl.runtime.AgentProgram;
import masl.runtime.Arrival;
import masl.runtime.EntryDefinition;
import masl.runtime.Mission;
import masl.runtime.MissionOutcome;
import masl.runtime.Mode;
import masl.runtime.scheduling.PoolScheduler;
import masl.runtime.trace.TraceEvent;
import masl.translator.MissionLoader;

/**
 * How the end of a mission's one block scales with its agents, against its start: for each size,
 * a few missions on {@code new PoolScheduler(1)}, all in one JVM, of programs whose agents leave
 * {@code main} in four ways. {@code sync}: the lock-step benchmark's program
 * ({@link MaslLockStep#source}); each agent waits out at the exit barrier, the last one lets every
 * member go. {@code async}: the same loop in an asynchronous {@code main}; each agent leaves by
 * itself. {@code break}: the loop in a synchronous child {@code work} of {@code main}, left with
 * {@code break(main)}, both blocks at once. {@code fail}: half the agents die while the other half
 * waits out ({@link HalfDie}).
 *
 * <p>Per mission it prints: its time; the start (building the mission to its first trip, or to its
 * first leave when nothing trips); the worker's CPU time from the first trip to the last (the
 * steps); the end (the last trip, or the first leave, to the end of {@code main}'s wave) and the
 * worker's CPU time over it; the time from the wave's end to the mission's (every agent finished).
 * Not a test and not part of {@code gradle bench}:
 * {@code gradle missionEndProbe -PprobeArgs="steps missions size..."} (defaults 20, 3, 1,000
 * 10,000 100,000).
 */
final class MissionEndProbe {

    private MissionEndProbe() {
    }

    public static void main(String[] args) throws Exception {
        int steps = args.length > 0 ? Integer.parseInt(args[0]) : 20;
        int missions = args.length > 1 ? Integer.parseInt(args[1]) : 3;
        int[] sizes = args.length > 2
                ? IntStream.range(2, args.length).map(i -> Integer.parseInt(args[i])).toArray()
                : new int[] {1_000, 10_000, 100_000};
        for (int agents : sizes) {
            for (Shape shape : Shape.values()) {
                MissionLoader program = MaslLockStep.compile(shape.source(agents, steps));
                for (int m = 0; m < missions; m++) {
                    System.out.println(shape.name().toLowerCase(Locale.ROOT) + " " + agents + " "
                            + measure(program.newMission(), true));
                }
            }
            for (int m = 0; m < missions; m++) {
                System.out.println("fail " + agents + " " + measure(HalfDie.mission(agents), false));
            }
        }
    }

    /** How the agents leave {@code main}. */
    private enum Shape {
        SYNC("synchronous entry main (true) {\n%s}\n"),
        ASYNC("asynchronous entry main (true) {\n%s}\n"),
        BREAK("synchronous entry main (true) {\n synchronous entry work (true) {\n%s  break(main);\n }\n}\n");

        private final String block;

        Shape(String block) {
            this.block = block;
        }

        String source(int agents, int steps) {
            String names = IntStream.range(0, agents).mapToObj(i -> "a" + i).collect(Collectors.joining(", "));
            String loop = "  local int i = 0;\n  while (i < " + steps + ") {\n    i++;\n  }\n";
            return "import Default.xml as Default;\nDefault " + names + " = newAgent(Default);\n"
                    + block.formatted(loop);
        }
    }

    /**
     * {@code fail}: in a synchronous {@code main}, the even agents wait out at its end at once,
     * the odd ones take one step and then their programs die (an {@code Error} escapes), each
     * leaving {@code main} while half the wave waits out; the last death lets them go. Written
     * by hand: a MASL program cannot let an error escape.
     */
    private static final class HalfDie extends AgentProgram {
        private static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);
        private final boolean dies;

        private HalfDie(boolean dies) {
            this.dies = dies;
        }

        static Mission.Builder mission(int agents) {
            Mission.Builder builder = Mission.builder().main(MAIN);
            for (int i = 0; i < agents; i++) {
                boolean dies = i % 2 == 1;
                builder.agent("a" + i, new AgentImplementation() { }, self -> new HalfDie(dies));
            }
            return builder;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0 -> {
                        pc = 1;
                        if (ctx.enter(MAIN, true) == Arrival.WAITING) {
                            return;
                        }
                    }
                    case 1 -> {
                        pc = dies ? 2 : 3;
                        if (!(dies ? ctx.stepBoundary() : ctx.leave(MAIN))) {
                            return;
                        }
                    }
                    case 2 -> throw new AssertionError("the program dies while half its wave waits out");
                    case 3 -> {
                        pc = 4;
                        if (!ctx.endOfSequence(MAIN.sequence())) {
                            return;
                        }
                    }
                    default -> {
                        ctx.finish();
                        return;
                    }
                }
            }
        }
    }

    /** Runs one mission; {@code completes}: it must complete, else its agents' deaths make it fail. */
    private static String measure(Mission.Builder builder, boolean completes) throws InterruptedException {
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        Marks marks = new Marks(threads);
        long built = System.nanoTime();
        Mission mission = builder
                .scheduler(new PoolScheduler(1))
                .journal(new StringBuilder())
                .trace(marks::record)
                .build();
        MissionOutcome outcome = mission.run(Duration.ofMinutes(30));
        if (completes) {
            outcome.requireCompleted();
        } else if (outcome.status() != MissionOutcome.Status.FAILED) {
            throw new IllegalStateException("the agents' deaths do not fail the mission: " + outcome);
        }
        long finished = System.nanoTime();
        long endFrom = marks.lastTrip != 0 ? marks.lastTrip : marks.firstLeave;
        long cpuFrom = marks.lastTrip != 0 ? marks.lastTripCpu : marks.firstLeaveCpu;
        long startTo = marks.firstTrip != 0 ? marks.firstTrip : marks.firstLeave;
        return String.format(Locale.ROOT, "mission %.1f ms: start %.1f ms, steps' worker CPU %.1f ms, end %.1f ms "
                + "(worker CPU %.1f ms), then finished in %.1f ms", (finished - built) / 1e6, (startTo - built) / 1e6,
                (marks.lastTripCpu - marks.firstTripCpu) / 1e6,
                (marks.mainEnded - endFrom) / 1e6, (marks.mainEndedCpu - cpuFrom) / 1e6,
                (finished - marks.mainEnded) / 1e6);
    }

    /** The moments of one mission, each with the CPU time of the thread that recorded it (the one worker). */
    private static final class Marks {
        private final ThreadMXBean threads;
        long firstTrip;
        long firstTripCpu;
        long lastTrip;
        long lastTripCpu;
        long firstLeave;
        long firstLeaveCpu;
        long mainEnded;
        long mainEndedCpu;

        Marks(ThreadMXBean threads) {
            this.threads = threads;
        }

        void record(TraceEvent event) {
            if (event instanceof TraceEvent.BarrierTripped) {
                lastTrip = System.nanoTime();
                lastTripCpu = threads.getCurrentThreadCpuTime();
                if (firstTrip == 0) {
                    firstTrip = lastTrip;
                    firstTripCpu = lastTripCpu;
                }
            } else if (event instanceof TraceEvent.Left && firstLeave == 0) {
                firstLeave = System.nanoTime();
                firstLeaveCpu = threads.getCurrentThreadCpuTime();
            } else if (event instanceof TraceEvent.WaveEnded ended && ended.block().equals("main")) {
                mainEnded = System.nanoTime();
                mainEndedCpu = threads.getCurrentThreadCpuTime();
            }
        }
    }
}
