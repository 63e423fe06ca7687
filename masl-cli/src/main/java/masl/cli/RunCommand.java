package masl.cli;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.PrintStream;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.time.Duration;
import masl.runtime.Mission;
import masl.runtime.MissionOutcome;
import masl.runtime.SeededScheduler;
import masl.runtime.ThreadPerAgentScheduler;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.trace.JsonLinesTrace;
import masl.translator.MissionLoader;
import masl.translator.source.SourceFile;

/**
 * {@code masl run}: translate, compile in memory, run in this process (generated-code contract §5).
 * The journal goes to standard output as it grows; diagnostics and the report of a failed mission
 * to standard error.
 */
final class RunCommand {

    /** "No limit": long enough for any mission, short enough for the runtime's deadline arithmetic. */
    private static final Duration NO_TIMEOUT = Duration.ofDays(3650);

    private final PrintStream out;
    private final PrintStream err;

    RunCommand(PrintStream out, PrintStream err) {
        this.out = out;
        this.err = err;
    }

    int run(CommandLine line, SourceFile source) throws UsageException {
        if (line.threads && line.seed != null) {
            throw new UsageException("--threads and --seed choose two different schedulers: give one of them");
        }
        if (!line.platform.equals("jade") && (line.mainHost != null || line.mainPort != null)) {
            throw new UsageException("--main-host and --main-port join a JADE platform: give them with --platform jade");
        }
        if (!line.platform.equals("jade") && (line.place != null || line.port != null || line.secretFile != null)) {
            throw new UsageException("--place, --port and --secret-file are for a JADE platform: give them with"
                    + " --platform jade");
        }
        AgentPath agentPath = AgentPath.parse(line.agentPath);
        Pipeline.Loaded compiled = Pipeline.load(source, agentPath, err);
        if (compiled == null) {
            return Masl.PROGRAM_ERRORS;
        }
        MissionLoader loaded = compiled.loader();
        Duration timeout = line.timeoutSeconds == null ? NO_TIMEOUT : Duration.ofSeconds(line.timeoutSeconds);
        if (line.platform.equals("jade")) {
            JadeRun jade = new JadeRun(line, source, agentPath, loaded, out, err);
            Writer trace = openTrace(line.traceFile);
            try {
                return report(jade.run(trace == null ? null : new JsonLinesTrace(trace), timeout), null);
            } finally {
                out.flush();
                closeTrace(trace, line.traceFile);
            }
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
        builder.journal(out);
        Writer trace = openTrace(line.traceFile);
        if (trace != null) {
            builder.trace(new JsonLinesTrace(trace));
        }
        try {
            return report(runStoppable(builder.build(), timeout), line.seed);
        } finally {
            out.flush();
            closeTrace(trace, line.traceFile);
        }
    }

    /** Runs the mission; Ctrl-C stops it (its journal so far is flushed, the exit status is 2). */
    private static MissionOutcome runStoppable(Mission mission, Duration timeout) {
        Thread stopper = new Thread(mission::stop, "masl-stop");
        Runtime.getRuntime().addShutdownHook(stopper);
        try {
            return mission.run(timeout);
        } catch (InterruptedException interrupted) {
            Thread.currentThread().interrupt();
            mission.stop();
            return new MissionOutcome(MissionOutcome.Status.STOPPED, mission.journal().text(),
                    java.util.Optional.empty(), "");
        } finally {
            try {
                Runtime.getRuntime().removeShutdownHook(stopper);
            } catch (IllegalStateException shuttingDown) {
                // The JVM is exiting because of Ctrl-C: the hook is running, as it should.
            }
        }
    }

    private int report(MissionOutcome outcome, Long seed) {
        if (outcome.completed()) {
            return Masl.OK;
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
        if (seed != null) {
            err.println("masl: the same run again: --seed " + seed);
        }
        return Masl.MISSION_FAILED;
    }

    private static Writer openTrace(String file) throws UsageException {
        if (file == null) {
            return null;
        }
        try {
            return new BufferedWriter(Files.newBufferedWriter(Path.of(file), StandardCharsets.UTF_8));
        } catch (IOException | InvalidPathException cannotWrite) {
            throw new UsageException("cannot write the trace to " + file + ": " + cannotWrite.getMessage());
        }
    }

    private void closeTrace(Writer trace, String file) {
        if (trace == null) {
            return;
        }
        try {
            trace.close();
        } catch (IOException cannotWrite) {
            err.println("masl: the trace " + file + " is incomplete: " + cannotWrite.getMessage());
        }
    }
}
