package masl.bench;

import java.time.Duration;
import java.util.concurrent.Callable;
import java.util.function.Supplier;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import masl.runtime.Mission;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.scheduling.PoolScheduler;
import masl.runtime.scheduling.Scheduler;
import masl.runtime.scheduling.ThreadPerAgentScheduler;
import masl.runtime.trace.TraceEvent;
import masl.translator.MissionLoader;
import masl.translator.Translation;
import masl.translator.Translator;
import masl.translator.source.SourceFile;

/**
 * MASL itself: a program of N agents in one synchronous block looping over a trivial instruction,
 * translated and compiled as {@code masl run} does, run on the default pool (one worker per core)
 * or, as the thesis's runtime did, on a platform thread per agent ({@code masl run --threads}).
 * Steps are the barrier trips of the mission's trace.
 */
final class MaslLockStep implements LockStepRun {

    private final String name;
    /**
     * The program of the latest row, compiled once and shared by its runs: a user's JVM runs one
     * mission's classes, while classes compiled anew for each run would each be compiled again by
     * the JIT, and would make the runtime's calls into the program megamorphic. Only one is kept,
     * so that no program outlives its row to weigh on the sections after.
     */
    private String compiledSource;
    private MissionLoader compiled;
    private final Supplier<Scheduler> scheduler;

    private MaslLockStep(String name, Supplier<Scheduler> scheduler) {
        this.name = name;
        this.scheduler = scheduler;
    }

    static MaslLockStep onPool() {
        return new MaslLockStep("MASL", PoolScheduler::new);
    }

    static MaslLockStep threadPerAgent() {
        return new MaslLockStep("MASL threads", ThreadPerAgentScheduler::new);
    }

    @Override
    public String name() {
        return name;
    }

    @Override
    public Callable<Double> prepare(int agents, int steps) throws Exception {
        MissionLoader program = compiled(source(agents, steps));
        StepClock clock = new StepClock();
        Mission mission = program.newMission()
                .scheduler(scheduler.get())
                .journal(new StringBuilder())
                .trace(event -> {
                    if (event instanceof TraceEvent.BarrierTripped) {
                        clock.stepEnded();
                    }
                })
                .build();
        return () -> {
            mission.run(Duration.ofMinutes(10)).requireCompleted();
            return clock.stepsPerSecond();
        };
    }

    private MissionLoader compiled(String source) {
        if (!source.equals(compiledSource)) {
            compiled = null;
            compiled = compile(source);
            compiledSource = source;
        }
        return compiled;
    }

    static String source(int agents, int steps) {
        String names = IntStream.range(0, agents).mapToObj(i -> "a" + i).collect(Collectors.joining(", "));
        return """
                import Default.xml as Default;
                Default %s = newAgent(Default);
                synchronous entry main (true) {
                  local int i = 0;
                  while (i < %d) {
                    i++;
                  }
                }
                """.formatted(names, steps);
    }

    static MissionLoader compile(String source) {
        AgentPath shippedAgentsOnly = AgentPath.parse("");
        Translation translation = new Translator(shippedAgentsOnly).translate(SourceFile.of("lockstep.masl", source));
        if (!translation.succeeded()) {
            throw new IllegalStateException("the benchmark's program does not translate: " + translation.diagnostics().sorted());
        }
        return MissionLoader.load(translation, shippedAgentsOnly);
    }
}
