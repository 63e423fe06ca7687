package masl.testing;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.LongStream;
import masl.runtime.Mission;
import masl.runtime.MissionOutcome;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.trace.MemoryTrace;
import masl.translator.MissionLoader;
import masl.translator.Translation;
import masl.translator.Translator;
import masl.translator.diagnostics.DiagnosticPrinter;
import masl.translator.source.SourceFile;

/**
 * A MASL mission under test: translated and compiled once, then run as many times as a test
 * wants, each run with a fresh mission, journal and trace.
 *
 * <pre>{@code
 * MaslMission e2 = MaslMission.fromFile(Path.of("missions/e2.masl"));
 * e2.run().assertJournal("n=5\nmine=1\n...");                          // the pool, as masl run
 * e2.explore(500).assertEveryRun(run -> run.assertEveryBefore("n=.*", "mine=.*"));
 * }</pre>
 *
 * A program with errors fails the test with its diagnostics ({@code file:line:col: error: ...}).
 */
public final class MaslMission {

    /** Long enough for any test mission; a mission that hangs ends as TIMED_OUT, never hangs a test. */
    private static final Duration DEFAULT_TIMEOUT = Duration.ofSeconds(60);

    private final SourceFile source;
    private String agentPath = "";
    private Duration timeout = DEFAULT_TIMEOUT;
    private Duration callTimeout;
    private MissionLoader loaded;

    private MaslMission(SourceFile source) {
        this.source = source;
    }

    /** The program in {@code file}; descriptors are looked up next to it first. */
    public static MaslMission fromFile(Path file) {
        try {
            return new MaslMission(SourceFile.read(file));
        } catch (IOException unreadable) {
            throw new UncheckedIOException("cannot read " + file, unreadable);
        }
    }

    /** A program given as text, named {@code name} in diagnostics and failures. */
    public static MaslMission fromString(String name, String text) {
        return new MaslMission(SourceFile.of(name, text));
    }

    /** Folders and jars with descriptors and their classes, {@code :}-separated, as {@code --agent-path}. */
    public MaslMission agentPath(String path) {
        this.agentPath = path;
        this.loaded = null;
        return this;
    }

    /** How long a run may take before it is stopped and reported as TIMED_OUT (default 60 s). */
    public MaslMission timeout(Duration timeout) {
        this.timeout = timeout;
        return this;
    }

    /**
     * Bounds every primitive call as {@code masl run --call-timeout} does: a call running longer gives
     * its caller the default value and {@code timeout}. Unbounded unless set.
     */
    public MaslMission callTimeout(Duration callTimeout) {
        this.callTimeout = callTimeout;
        return this;
    }

    /** One run on the pool scheduler, as {@code masl run} runs it. */
    public MissionRun run() {
        return runWith(Schedule.pool());
    }

    public MissionRun runWith(Schedule schedule) {
        MemoryTrace trace = new MemoryTrace();
        MissionOutcome outcome;
        try {
            Mission.Builder mission = loaded().newMission()
                    .scheduler(schedule.newScheduler())
                    .journal(new StringBuilder())
                    .trace(trace);
            if (callTimeout != null) {
                mission.callTimeout(callTimeout);
            }
            outcome = mission.build().run(timeout);
        } catch (InterruptedException interrupted) {
            Thread.currentThread().interrupt();
            throw new AssertionError(source.name() + " was interrupted under " + schedule, interrupted);
        }
        return new MissionRun(source.name(), schedule, outcome, trace.events());
    }

    /** Runs under seeds 0 to {@code seeds - 1}. */
    public Exploration explore(int seeds) {
        return explore(LongStream.range(0, seeds), 0);
    }

    /** Runs under each of {@code seeds}, then {@code poolRuns} times on the real pool. */
    public Exploration explore(LongStream seeds, int poolRuns) {
        List<MissionRun> runs = new ArrayList<>();
        seeds.forEach(seed -> runs.add(runWith(Schedule.seed(seed))));
        for (int i = 0; i < poolRuns; i++) {
            runs.add(run());
        }
        return new Exploration(source.name(), runs);
    }

    private MissionLoader loaded() {
        if (loaded == null) {
            AgentPath path = AgentPath.parse(agentPath);
            Translation translation = new Translator(path).translate(source);
            if (!translation.succeeded()) {
                throw new AssertionError(diagnostics(translation));
            }
            loaded = MissionLoader.load(translation, path);
        }
        return loaded;
    }

    private String diagnostics(Translation translation) {
        return new DiagnosticPrinter(Map.of(source.name(), source.text())).report(translation.diagnostics().sorted());
    }
}
