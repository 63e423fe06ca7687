package masl.testing;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.stream.LongStream;
import masl.runtime.MissionOutcome;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.diagnostic.DiagnosticPrinter;
import masl.runtime.scheduling.ReplayCommand;
import masl.runtime.trace.MemoryTrace;
import masl.translator.MissionLoader;
import masl.translator.Translation;
import masl.translator.Translator;
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
 * A program with errors fails the test with its diagnostics ({@code file:line:col: error: ...}). A run
 * under a seed that fails an assertion says how to run it again: {@code runWith(Schedule.seed(n))},
 * and for a program read from a file, the {@code masl run} command with its agent path and call
 * timeout ({@link ReplayCommand}).
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

    /** One run in this JVM under {@code schedule}. */
    public MissionRun runWith(Schedule schedule) {
        return runOn(schedule);
    }

    /** One run on {@code platform}: in this JVM under a {@link Schedule}, or inside an agent platform. */
    public MissionRun runOn(MissionPlatform platform) {
        MemoryTrace trace = new MemoryTrace();
        MissionOutcome outcome;
        try {
            outcome = platform.run(translated(), trace, timeout);
        } catch (InterruptedException interrupted) {
            Thread.currentThread().interrupt();
            throw new AssertionError(source.name() + " was interrupted " + platform, interrupted);
        }
        return new MissionRun(source.name(), platform, outcome, trace.events(), replayHint(platform));
    }

    /** How to run a failed seeded run again, in the test and with the masl command; empty for other runs. */
    private Optional<String> replayHint(MissionPlatform platform) {
        if (!(platform instanceof Schedule.Seeded seeded)) {
            return Optional.empty();
        }
        String inTheTest = "runWith(Schedule.seed(" + seeded.seed() + "L))";
        if (source.folder() == null) {
            return Optional.of("replay: " + inTheTest);
        }
        List<String> options = new ArrayList<>();
        if (!agentPath.isEmpty()) {
            options.addAll(List.of("--agent-path", agentPath));
        }
        if (callTimeout != null) {
            options.addAll(List.of("--call-timeout", Long.toString(callTimeout.toMillis())));
        }
        return Optional.of("replay: " + inTheTest + ", or " + ReplayCommand.masl(source.name(), options).forSeed(seeded.seed()));
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

    /** The program, translated and compiled at the first run, with this mission's options as they are now. */
    private TranslatedMission translated() {
        AgentPath path = AgentPath.parse(agentPath);
        if (loaded == null) {
            Translation translation = new Translator(path).translate(source);
            if (!translation.succeeded()) {
                throw new AssertionError(diagnostics(translation));
            }
            loaded = MissionLoader.load(translation, path);
        }
        return new TranslatedMission(loaded, path.withFirst(source.folder()), Optional.ofNullable(callTimeout));
    }

    private String diagnostics(Translation translation) {
        return new DiagnosticPrinter(Map.of(source.name(), source.text())).report(translation.diagnostics().sorted());
    }
}
