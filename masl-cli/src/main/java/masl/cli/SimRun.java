package masl.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.time.Duration;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import masl.runtime.MissionOutcome;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.diagnostic.Diagnostic;
import masl.runtime.diagnostic.DiagnosticPrinter;
import masl.sim.scenario.RunOptions;
import masl.sim.scenario.Scenario;
import masl.sim.scenario.ScenarioException;
import masl.sim.scenario.ScenarioLoader;
import masl.sim.scenario.ScenarioRunner;
import masl.sim.scenario.SimulationResult;
import masl.sim.xode.XodeSource;
import masl.translator.source.SourceFile;

/**
 * {@code masl run --sim SCENARIO}: the scenario names the mission file; the mission is translated,
 * compiled in memory and run on the scenario's simulated robots by {@link ScenarioRunner}. The
 * journal (only the journal) goes to standard output; trajectories, events, trace, journal and the
 * trajectory picture are written to {@code --out}, by default the folder {@code NAME.out} next to
 * the scenario file {@code NAME.scenario.xml}. Folders holding the scenario's descriptor files are
 * searched for descriptors before {@code --agent-path}. An output folder that cannot be written is
 * reported before anything runs, and fails the run (status 2) as a trace that cannot be written
 * does; a signal stops the mission and the output is still written.
 */
final class SimRun {

    private static final Duration NO_TIMEOUT = Duration.ofDays(3650);

    private final PrintStream out;
    private final PrintStream err;
    private final Progress progress;
    /** The simulated time of the latest physics step, in seconds, for the progress line. */
    private volatile double simulated;
    /** The simulated time and the run's real time when the first progress line was made; -1 before it (the progress lines' thread). */
    private double firstLineSimulated = -1;
    private long firstLineElapsed;

    SimRun(PrintStream out, PrintStream err, Progress progress) {
        this.out = out;
        this.err = err;
        this.progress = progress;
    }

    int run(CommandLine line) throws UsageException {
        if (!line.operands.isEmpty()) {
            throw new UsageException("masl run --sim takes the scenario only: its <mission file=...> names the program");
        }
        if (line.callTimeoutMillis != null) {
            throw new UsageException("--call-timeout and --sim: simulated robots' primitives are not bounded yet");
        }
        if (line.threads) {
            throw new UsageException("--threads and --sim: the scenario chooses how agents and physics share time");
        }
        if (line.platform.equals("jade") || line.mainHost != null || line.mainPort != null || line.port != null
                || line.localHost != null || line.place != null || line.deploy != null || line.secretFile != null) {
            throw new UsageException("--platform jade, --main-host, --main-port, --port, --local-host, --place, --deploy"
                    + " and --secret-file are for a JADE platform: --sim runs the mission and its simulated robots in this JVM");
        }
        if (line.traceFile != null) {
            throw new UsageException("--trace and --sim: the simulation writes its trace to its output folder"
                    + " (trace.jsonl in --out DIR, by default NAME.out beside the scenario)");
        }
        Path scenarioFile = existingFile(line.scenarioFile);
        Scenario scenario;
        try {
            scenario = new ScenarioLoader().load(scenarioFile);
        } catch (ScenarioException invalid) {
            printErrors(invalid.diagnostics());
            return Masl.PROGRAM_ERRORS;
        }
        if (scenario.mission().isEmpty()) {
            printErrors(List.of(Diagnostic.error(scenarioFile.toString(), 1, 1,
                    "the scenario names no mission (<mission file=\"NAME.masl\"/>)")));
            return Masl.PROGRAM_ERRORS;
        }
        SourceFile source = readMission(scenario.mission().get());
        if (source == null) {
            return Masl.PROGRAM_ERRORS;
        }
        AgentPath agentPath = AgentPath.parse(agentPathWithDescriptors(scenario, line.agentPath));
        Pipeline.Loaded loaded = Pipeline.load(source, agentPath, err, progress);
        if (loaded == null) {
            return Masl.PROGRAM_ERRORS;
        }
        Path output = outputFolder(line.outputFolder, scenarioFile);
        refuseOverwritingInputs(output, scenarioFile, scenario, source, agentPath).refuseJournalOverwriting(out);
        String unwritable = OutputFolder.cannotWrite(output);
        if (unwritable != null) {
            // A run whose output cannot be written fails, as one whose trace cannot (RunCommand).
            err.println("masl: cannot write the simulation's output to " + output + ": " + unwritable);
            return Masl.MISSION_FAILED;
        }
        JournalOutput journal = new JournalOutput(out);
        try (StopOnSignal signals = new StopOnSignal(err)) {
            RunOptions options = RunOptions.defaults()
                    .withJournal(progress.journal(journal))
                    .withOutput(output)
                    .withTraceLimit(line.traceLimit())
                    .whenWarned(warnings -> new DiagnosticPrinter(Map.of()).print(warnings, err))
                    .withTimeout(line.timeoutSeconds == null ? NO_TIMEOUT : Duration.ofSeconds(line.timeoutSeconds))
                    .whenReady(mission -> {
                        journal.whenFailed(() -> mission.stop(RunCommand.JOURNAL_LOST));
                        if (!signals.stops(mission::stop)) {
                            mission.stop(StopOnSignal.REASON);
                        }
                    })
                    .withProgress(seconds -> {
                        simulated = seconds;
                        progress.tick();
                    });
            SimulationResult result;
            progress.begin(elapsed -> status(scenario, elapsed));
            try {
                result = new ScenarioRunner(seeded(scenario, line.seed)).run(loaded.loader().program(), options);
            } finally {
                progress.end();
            }
            if (result.traceCut()) {
                err.println("masl: " + TraceOutput.cutAt(output.resolve(ScenarioRunner.TRACE), line.traceLimit()));
            }
            return report(result, scenario, output, signals, journal);
        } catch (ScenarioException doesNotFit) {
            printErrors(doesNotFit.diagnostics());
            return Masl.PROGRAM_ERRORS;
        } catch (IOException cannotWrite) {
            err.println("masl: cannot write the simulation's output to " + output + ": "
                    + OutputFolder.reason(cannotWrite));
            return Masl.MISSION_FAILED;
        } catch (InterruptedException interrupted) {
            Thread.currentThread().interrupt();
            err.println("masl: the mission stopped");
            return Masl.MISSION_FAILED;
        } finally {
            out.flush();
        }
    }

    /**
     * {@code masl: simulated 12.3 s of 60 s, 1.02x real time, journal 4 lines}. The real-time factor
     * is the simulated time over the real time since the first line: before it, the run was loading
     * the scenario and building its worlds, so the first line has no factor (it would be near zero
     * and mean nothing).
     */
    /** A scenario's errors as a program's are printed: each with its source line and a caret, then their count. */
    private void printErrors(List<Diagnostic> errors) {
        new DiagnosticPrinter(Map.of()).print(errors, err);
    }

    private String status(Scenario scenario, long elapsedNanos) {
        double now = simulated;
        String of = scenario.duration() > 0 ? String.format(java.util.Locale.ROOT, " of %.0f s", scenario.duration()) : "";
        String rate = "";
        if (firstLineSimulated < 0) {
            firstLineSimulated = now;
            firstLineElapsed = elapsedNanos;
        } else if (elapsedNanos > firstLineElapsed) {
            rate = String.format(java.util.Locale.ROOT, ", %.2fx real time",
                    (now - firstLineSimulated) / ((elapsedNanos - firstLineElapsed) / 1e9));
        }
        long lines = progress.journalLines();
        return String.format(java.util.Locale.ROOT, "masl: simulated %.1f s%s%s, journal %d line%s",
                now, of, rate, lines, lines == 1 ? "" : "s");
    }

    /** {@code --seed} overrides the physics seed of the scenario; the lock-step scheduler draws from it. */
    private static Scenario seeded(Scenario scenario, Long seed) {
        if (seed == null) {
            return scenario;
        }
        return new Scenario(scenario.name(), scenario.source(), scenario.physics().withSeed(seed), scenario.mode(),
                scenario.slicesPerStep(), scenario.duration(), scenario.worlds(), scenario.agents(), scenario.faults(),
                scenario.initialisation(), scenario.mission(), scenario.samplePeriod());
    }

    /**
     * A simulated mission ends normally when it completes or when the scenario's duration has passed
     * (the runner stops it then); a deadlock, a crash or the wall-clock timeout fail it.
     */
    private int report(SimulationResult result, Scenario scenario, Path output, StopOnSignal signals,
            JournalOutput journal) {
        MissionOutcome outcome = result.outcome();
        boolean durationReached = outcome.status() == MissionOutcome.Status.STOPPED && scenario.duration() > 0
                && result.simulatedSeconds() >= scenario.duration() - 1e-6;
        if (journal.failed()) {
            err.println("masl: cannot write the journal to standard output");
            return Masl.MISSION_FAILED;
        }
        if (outcome.status() == MissionOutcome.Status.STOPPED && signals.signalled() && !durationReached) {
            err.println("masl: the mission was stopped by " + StopOnSignal.REASON + "; output in " + output);
            return Masl.MISSION_FAILED;
        }
        if (outcome.completed() || durationReached) {
            err.printf(java.util.Locale.ROOT, "masl: %.2f s simulated; output in %s%n", result.simulatedSeconds(), output);
            return Masl.OK;
        }
        err.println("masl: the mission " + switch (outcome.status()) {
            case DEADLOCKED -> "deadlocked: no agent can make progress";
            case TIMED_OUT -> "timed out";
            default -> "failed";
        });
        outcome.failure().ifPresent(failure -> err.println("  " + failure));
        if (!outcome.report().isEmpty()) {
            err.println(outcome.report().stripTrailing());
        }
        return Masl.MISSION_FAILED;
    }

    /** None of the files written to {@code output} may be one the run reads; the inputs, for the journal's check. */
    private static CommandInputs refuseOverwritingInputs(Path output, Path scenarioFile, Scenario scenario, SourceFile source,
            AgentPath agentPath) throws UsageException {
        CommandInputs inputs = CommandInputs.ofProgram(source, agentPath).add("the scenario", scenarioFile);
        scenario.worlds().forEach(world -> world.file().ifPresent(file -> inputs.add("the world", file)));
        for (Scenario.Agent agent : scenario.agents()) {
            agent.descriptor().ifPresent(file -> inputs.add("the descriptor", file));
            agent.body().flatMap(XodeSource::file).ifPresent(file -> inputs.add("the body", file));
        }
        for (String name : List.of(ScenarioRunner.TRAJECTORIES, ScenarioRunner.EVENTS, ScenarioRunner.TRACE,
                ScenarioRunner.JOURNAL, ScenarioRunner.PICTURE)) {
            inputs.refuseOverwriting("the output", output.resolve(name));
        }
        return inputs;
    }

    private static String agentPathWithDescriptors(Scenario scenario, String userPath) {
        Set<String> folders = new LinkedHashSet<>();
        scenario.agents().forEach(agent -> agent.descriptor()
                .ifPresent(file -> folders.add(file.toAbsolutePath().getParent().toString())));
        if (!userPath.isEmpty()) {
            folders.add(userPath);
        }
        return String.join(java.io.File.pathSeparator, folders);
    }

    static Path outputFolder(String option, Path scenarioFile) throws UsageException {
        if (option != null) {
            try {
                return Path.of(option);
            } catch (InvalidPathException bad) {
                throw new UsageException("not a folder name: " + option);
            }
        }
        String name = scenarioFile.getFileName().toString();
        String base = name.endsWith(".scenario.xml") ? name.substring(0, name.length() - ".scenario.xml".length())
                : name.endsWith(".xml") ? name.substring(0, name.length() - 4) : name;
        return scenarioFile.toAbsolutePath().resolveSibling(base + ".out");
    }

    private SourceFile readMission(Path file) {
        try {
            return SourceFile.read(file);
        } catch (IOException unreadable) {
            err.println("masl: the scenario's mission " + file + " cannot be read: " + unreadable.getMessage());
            return null;
        }
    }

    private static Path existingFile(String name) throws UsageException {
        try {
            Path file = Path.of(name);
            if (!Files.isRegularFile(file)) {
                throw new UsageException(name + ": no such scenario file");
            }
            return file;
        } catch (InvalidPathException bad) {
            throw new UsageException("not a file name: " + name);
        }
    }
}
