package masl.cli;

import java.io.PrintStream;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import masl.runtime.Mission;
import masl.runtime.MissionOutOfMemory;
import masl.runtime.MissionOutcome;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.scheduling.ReplayCommand;
import masl.runtime.scheduling.SeededScheduler;
import masl.runtime.scheduling.ThreadPerAgentScheduler;
import masl.translator.MissionLoader;
import masl.translator.cache.CompiledMissionCache;
import masl.translator.source.SourceFile;

/**
 * {@code masl run}: translate, compile in memory, run in this process (generated-code contract §5).
 * The journal goes to standard output as it grows; diagnostics and the report of a failed mission
 * to standard error.
 */
final class RunCommand {

    /** Why a mission whose journal cannot be written was stopped, as its {@code mission-ended} record says. */
    static final String JOURNAL_LOST = "the journal cannot be written";

    /** "No limit": long enough for any mission, short enough for the runtime's deadline arithmetic. */
    private static final Duration NO_TIMEOUT = Duration.ofDays(3650);

    private final PrintStream out;
    private final PrintStream err;
    private final Progress progress;
    private final CompiledMissionCache cache;

    /** @param cache where compiled missions are kept between runs */
    RunCommand(PrintStream out, PrintStream err, Progress progress, CompiledMissionCache cache) {
        this.out = out;
        this.err = err;
        this.progress = progress;
        this.cache = cache;
    }

    int run(CommandLine line, SourceFile source) throws UsageException {
        if (line.threads && line.seed != null) {
            throw new UsageException("--threads and --seed choose two different schedulers: give one of them");
        }
        if (line.traceLimitGiven != null && line.traceFile == null) {
            throw new UsageException("--trace-limit cuts the trace of --trace FILE: give it with --trace (or with --sim)");
        }
        if (line.outputFolder != null) {
            throw new UsageException("--out is where --sim writes a simulation's outputs: give it with --sim SCENARIO"
                    + " (masl run FILE writes its journal to standard output and its trace to --trace FILE)");
        }
        if (!line.platform.equals("jade") && (line.mainHost != null || line.mainPort != null)) {
            throw new UsageException("--main-host and --main-port join a JADE platform: give them with --platform jade");
        }
        if (!line.platform.equals("jade") && (line.place != null || line.deploy != null || line.port != null
                || line.localHost != null || line.secretFile != null)) {
            throw new UsageException("--place, --deploy, --port, --local-host and --secret-file are for a JADE platform:"
                    + " give them with --platform jade");
        }
        try (StopOnSignal signals = new StopOnSignal(err)) {
            return translateAndRun(line, source, signals);
        } catch (TraceOutput.Unwritable lost) {
            err.println("masl: " + lost.getMessage());
            return Masl.MISSION_FAILED;
        }
    }

    private int translateAndRun(CommandLine line, SourceFile source, StopOnSignal signals)
            throws UsageException, TraceOutput.Unwritable {
        AgentPath agentPath = AgentPath.parse(line.agentPath);
        CommandInputs inputs = CommandInputs.ofProgram(source, agentPath).add("the placement file", line.place);
        inputs.refuseOverwriting("the trace", line.traceFile);
        inputs.refuseJournalOverwriting(out);
        MissionLoader loaded = load(line, source, agentPath);
        if (loaded == null) {
            return Masl.PROGRAM_ERRORS;
        }
        Duration timeout = line.timeoutSeconds == null ? NO_TIMEOUT : Duration.ofSeconds(line.timeoutSeconds);
        JournalOutput journal = new JournalOutput(out);
        if (line.platform.equals("jade")) {
            JadeRun jade = new JadeRun(line, source, agentPath, loaded, journal, err);
            TraceOutput trace = TraceOutput.open(line.traceFile, line.traceLimit());
            MissionOutcome outcome;
            try {
                outcome = jade.run(trace, timeout, signals);
            } finally {
                out.flush();
                trace.close();
            }
            return report(outcome, null, signals, journal, trace);
        }
        Mission.Builder builder;
        try {
            builder = loaded.newMission();
        } catch (MissionLoader.AgentCreationException cannotCreate) {
            err.println("masl: " + cannotCreate.getMessage());
            return Masl.PROGRAM_ERRORS;
        }
        if (line.threads) {
            builder.scheduler(new ThreadPerAgentScheduler());
        } else if (line.seed != null) {
            builder.scheduler(new SeededScheduler(line.seed));
        }
        if (line.callTimeoutMillis != null) {
            builder.callTimeout(Duration.ofMillis(line.callTimeoutMillis));
        }
        builder.journal(journal);
        TraceOutput trace = TraceOutput.open(line.traceFile, line.traceLimit());
        builder.trace(trace.trace());
        Mission mission = builder.build();
        journal.whenFailed(() -> mission.stop(JOURNAL_LOST));
        trace.whenFailed(() -> mission.stop(TraceOutput.TRACE_LOST));
        MissionOutcome outcome;
        try {
            if (!signals.stops(mission::stop)) {
                return Masl.MISSION_FAILED;
            }
            outcome = run(mission, timeout);
        } finally {
            out.flush();
            trace.close();
        }
        return report(outcome, line.seed == null ? null : replay(line, source), signals, journal, trace);
    }

    /** The compiled program, from the cache unless --no-cache; null when it has errors. */
    private MissionLoader load(CommandLine line, SourceFile source, AgentPath agentPath) {
        if (line.noCache) {
            Pipeline.Loaded compiled = Pipeline.load(source, agentPath, err, progress);
            return compiled == null ? null : compiled.loader();
        }
        return Pipeline.loadThroughCache(source, agentPath, err, progress, cache);
    }

    /** Runs the mission; a signal stops it ({@link StopOnSignal}). */
    private static MissionOutcome run(Mission mission, Duration timeout) {
        try {
            return mission.run(timeout);
        } catch (InterruptedException interrupted) {
            Thread.currentThread().interrupt();
            mission.stop();
            return new MissionOutcome(MissionOutcome.Status.STOPPED, mission.journal().text(), Optional.empty(), "");
        }
    }

    /**
     * The exit status of a run and its one report on standard error. A journal or a trace that could
     * not be written fails the run whatever the mission did; a signal's stop is said in one line; a
     * trace cut at its limit is said, and is no failure.
     */
    private int report(MissionOutcome outcome, String replay, StopOnSignal signals, JournalOutput journal,
            TraceOutput trace) {
        if (journal.failed()) {
            err.println("masl: cannot write the journal to standard output");
            return Masl.MISSION_FAILED;
        }
        Optional<String> traceLost = trace.lost();
        if (traceLost.isPresent()) {
            err.println("masl: " + traceLost.get());
            return Masl.MISSION_FAILED;
        }
        trace.cut().ifPresent(cut -> err.println("masl: " + cut));
        if (outcome.status() == MissionOutcome.Status.STOPPED && signals.signalled()) {
            err.println("masl: the mission was stopped by " + StopOnSignal.REASON);
            return Masl.MISSION_FAILED;
        }
        if (outcome.completed()) {
            return Masl.OK;
        }
        if (outcome.failure().orElse(null) instanceof PlatformFailure platform) {
            err.println("masl: " + platform.getMessage());
            return Masl.MISSION_FAILED;
        }
        if (outcome.status() == MissionOutcome.Status.FAILED && outcome.failure().orElse(null) instanceof MissionOutOfMemory) {
            err.println("masl: the mission ran out of memory: its data outgrew the heap's "
                    + MissionOutOfMemory.heapLimitMiB() + " MiB (java -Xmx, in JAVA_OPTS or MASL_OPTS, sets it)");
            err.println(outcome.report().stripTrailing());
            return Masl.MISSION_FAILED;
        }
        String what = switch (outcome.status()) {
            case DEADLOCKED -> "deadlocked: no agent can make progress";
            case TIMED_OUT -> "timed out";
            case STOPPED -> "stopped";
            default -> "failed";
        };
        err.println("masl: the mission " + what);
        outcome.failure().ifPresent(failure -> {
            for (Throwable cause = failure; cause != null; cause = cause.getCause()) {
                err.println("  " + (cause == failure ? "" : "caused by ") + cause);
            }
        });
        if (!outcome.report().isEmpty()) {
            err.println(outcome.report().stripTrailing());
        }
        if (replay != null) {
            err.println("masl: the same run again: " + replay);
        }
        return Masl.MISSION_FAILED;
    }

    /**
     * The command that runs this seeded run again where it was started: the build's task when a build
     * plug-in started masl ({@link ReplayCommand#PROPERTY}), otherwise masl run with the options that
     * make the run what it was.
     */
    private static String replay(CommandLine line, SourceFile source) {
        ReplayCommand command = ReplayCommand.fromSystemProperty().orElseGet(() -> {
            List<String> options = new ArrayList<>();
            if (!line.agentPath.isEmpty()) {
                options.addAll(List.of("--agent-path", line.agentPath));
            }
            if (line.timeoutSeconds != null) {
                options.addAll(List.of("--timeout", line.timeoutSeconds.toString()));
            }
            if (line.callTimeoutMillis != null) {
                options.addAll(List.of("--call-timeout", line.callTimeoutMillis.toString()));
            }
            return ReplayCommand.masl(source.name(), options);
        });
        return command.forSeed(line.seed);
    }

}
