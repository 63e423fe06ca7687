package masl.cli;

import java.io.IOException;
import java.io.InputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Map;
import masl.runtime.descriptor.AgentPath;
import masl.translator.compile.GeneratedCodeException;
import masl.translator.source.SourceFile;

/**
 * The {@code masl} command. Exit statuses (components.md): 0 success, 1 errors in the program or its
 * descriptors, 2 the mission failed (deadlock, crash, timeout, lost journal), 64 bad usage, 70 an
 * internal error (a bug of masl, reported as one, never as a stack trace); a run Ctrl-C or SIGTERM
 * stops ends with the JVM's 130 or 143 ({@link StopOnSignal}).
 */
public final class Masl {

    static final int OK = 0;
    static final int PROGRAM_ERRORS = 1;
    static final int MISSION_FAILED = 2;
    static final int USAGE = 64;
    static final int INTERNAL_ERROR = 70;

    static final String USAGE_TEXT = """
            usage: masl run FILE [--agent-path PATH] [--threads | --seed N] [--timeout SECONDS] [--trace FILE] [--quiet]
                           [--call-timeout MS] [--platform inproc|jade]
                           [--main-host HOST --main-port PORT | --port PORT]
                           [--place AGENT=CONTAINER,... | --place FILE] [--secret-file FILE]
                   masl container --main-host HOST --main-port PORT --name CONTAINER [--agent-path PATH]
                           [--timeout SECONDS] [--secret-file FILE]
                   masl run --sim SCENARIO [--out DIR] [--seed N] [--timeout SECONDS] [--agent-path PATH] [--quiet]
                   masl compile FILE -d DIR [--agent-path PATH] [--quiet]
                   masl check FILE [--agent-path PATH] [--quiet]
                   masl timeline TRACE -o FILE.html
                   masl lsp [--agent-path PATH]
              run       translate a MASL program, compile it in memory and run its mission in this process;
                        the journal (and only the journal) goes to standard output
                        with --sim, the mission the scenario names runs on its simulated robots; trajectories,
                        events, trace, journal and a picture go to --out (default: NAME.out beside NAME.scenario.xml)
              container join a JADE platform as container CONTAINER and host the bodies (the primitives) of the
                        agents a run --place puts there; their programs run in the run's JVM; ends with the mission
              compile   translate a MASL program into Java sources under DIR (one folder per package)
              check     report every error of a MASL program and of the descriptors it imports: all that
                        compile and run would report, as they translate and compile it, without running it
              timeline  draw a trace written by run --trace (or run --sim) as a self-contained HTML page: one
                        lane per agent over time, coloured by block, with barrier trips, waves, invocations,
                        events and failures; zoom, pan and filter it in a browser
              lsp       serve the Language Server Protocol on standard input and output for an editor: the
                        diagnostics of check on every change, completion, hover, go to definition, outline
            options:
              --agent-path PATH   folders and jars holding agent descriptors and their classes, ':'-separated;
                                  searched after the program's folder, before the descriptors masl ships
              --threads           run each agent on a thread of its own instead of a small pool
              --seed N            run on one thread, every scheduling choice drawn from seed N (replayable)
              --timeout SECONDS   stop the mission after SECONDS (default: no limit)
              --call-timeout MS   a primitive running longer than MS milliseconds gives its caller its default
                                  value and the event timeout; the mission goes on (default: no limit); with
                                  --platform jade it also bounds each FIPA agent's call from outside the mission
                                  (default for those: 10000)
              --trace FILE        write the trace (one JSON object per line) to FILE
              --quiet             no progress on standard error: by default, work running longer than a second
                                  (translating, compiling, a --sim run: simulated time, real-time factor,
                                  journal lines) is shown there, on one line rewritten on a terminal
              --platform P        inproc (default): run in this process; jade: run inside a JADE platform,
                                  one JADE agent per MASL agent, registered with the DF, answering FIPA requests
              --main-host HOST, --main-port PORT
                                  with --platform jade: join the platform whose main container listens there
                                  instead of starting one on loopback
              --port PORT         with --platform jade: the port of the main container run starts (default: a free one)
              --place AGENT=CONTAINER,... or FILE (lines AGENT=CONTAINER)
                                  with --platform jade: run these agents' bodies in the containers named (started
                                  with masl container), their programs in this JVM; other agents stay here
              --secret-file FILE  with --place (and for masl container): where run writes a fresh secret for the
                                  mission (owner-only, deleted at its end) and its containers read it; they obey
                                  only messages signed with it (default: .masl-mission-secret in this folder)
            exit status: 0 success, 1 errors in the program or its descriptors, 2 the mission failed,
                         deadlocked or timed out, or its journal could not be written, 64 bad usage,
                         70 internal error, 130 or 143 stopped by Ctrl-C or SIGTERM
            """;

    private final InputStream in;
    private final PrintStream out;
    private final PrintStream err;
    private final Progress.Settings progress;

    public Masl(PrintStream out, PrintStream err) {
        this(System.in, out, err);
    }

    /** @param in what {@code masl lsp} reads its client's messages from */
    public Masl(InputStream in, PrintStream out, PrintStream err) {
        this(in, out, err, Progress.Settings.standard());
    }

    /**
     * This command without progress lines, as if every run had {@code --quiet}: for a caller that
     * reads standard error as the diagnostics alone (tests, tools embedding the command).
     */
    public Masl withoutProgress() {
        return new Masl(in, out, err, progress.quiet(true));
    }

    /** @param progress how long work is reported on {@code err} (tests give their own clock) */
    Masl(InputStream in, PrintStream out, PrintStream err, Progress.Settings progress) {
        this.in = in;
        this.out = out;
        this.err = err;
        this.progress = progress;
    }

    /**
     * {@code masl --help}, {@code masl help [COMMAND]}, or {@code --help}/{@code -h} among a
     * command's words, whatever else they hold: the usage, on standard output, status 0.
     */
    private static boolean asksForHelp(String... args) {
        if (args.length > 0 && args[0].equals("help")) {
            return true;
        }
        for (String arg : args) {
            if (arg.equals("--help") || arg.equals("-h")) {
                return true;
            }
        }
        return false;
    }

    /** Runs one invocation and returns its exit status; never throws. */
    public int run(String... args) {
        try {
            if (asksForHelp(args)) {
                out.print(USAGE_TEXT);
                return OK;
            }
            CommandLine line = CommandLine.parse(args);
            try (Progress shown = new Progress(err, progress.quiet(line.quiet))) {
                return dispatch(line, shown);
            }
        } catch (UsageException usage) {
            err.println("masl: " + usage.getMessage());
            err.print(USAGE_TEXT);
            return USAGE;
        } catch (GeneratedCodeException bug) {
            err.println("masl: internal error: the Java generated for this program does not compile; please report it"
                    + " with the program" + savedReport(bug));
            return INTERNAL_ERROR;
        } catch (RuntimeException | StackOverflowError | OutOfMemoryError | LinkageError bug) {
            err.println("masl: internal error, please report it with the program that caused it: " + bug);
            return INTERNAL_ERROR;
        }
    }

    private int dispatch(CommandLine line, Progress progress) throws UsageException {
        return switch (line.command) {
            case "check" -> check(line, progress);
            case "compile" -> compile(line, progress);
            case "run" -> line.scenarioFile != null ? new SimRun(out, err, progress).run(line)
                    : new RunCommand(out, err, progress).run(line, readProgram(line.singleFile()));
            case "timeline" -> new TimelineCommand(err).run(line);
            case "container" -> new ContainerCommand(out, err).run(line);
            case "lsp" -> new LspCommand(in, out, err).run(line);
            default -> throw new UsageException("unknown command '" + line.command + "'");
        };
    }

    /** Keeps javac's messages for the bug report in a file, since the user is not meant to read them. */
    private static String savedReport(GeneratedCodeException bug) {
        try {
            Path report = Files.createTempFile("masl-internal-error-", ".txt");
            Files.writeString(report, bug.getMessage());
            return " (details in " + report + ")";
        } catch (IOException | RuntimeException cannotSave) {
            return "";
        }
    }

    private int check(CommandLine line, Progress progress) throws UsageException {
        SourceFile source = readProgram(line.singleFile());
        return Pipeline.load(source, AgentPath.parse(line.agentPath), err, progress) == null ? PROGRAM_ERRORS : OK;
    }

    private int compile(CommandLine line, Progress progress) throws UsageException {
        SourceFile source = readProgram(line.singleFile());
        if (line.outputFolder == null) {
            throw new UsageException("masl compile needs -d DIR, the folder to write the Java sources into");
        }
        Pipeline.Loaded loaded = Pipeline.load(source, AgentPath.parse(line.agentPath), err, progress);
        if (loaded == null) {
            return PROGRAM_ERRORS;
        }
        Path folder = Path.of(line.outputFolder);
        for (Map.Entry<String, String> unit : loaded.translation().javaSources().entrySet()) {
            Path file = folder.resolve(unit.getKey().replace('.', '/') + ".java");
            try {
                Files.createDirectories(file.getParent());
                Files.writeString(file, unit.getValue());
            } catch (IOException | InvalidPathException cannotWrite) {
                err.println("masl: cannot write " + file + ": " + cannotWrite.getMessage());
                return USAGE;
            }
        }
        return OK;
    }

    private static SourceFile readProgram(String name) throws UsageException {
        Path file;
        try {
            file = Path.of(name);
        } catch (InvalidPathException bad) {
            throw new UsageException("not a file name: " + name);
        }
        if (!Files.isRegularFile(file)) {
            throw new UsageException(name + ": no such file");
        }
        try {
            return SourceFile.read(file);
        } catch (IOException unreadable) {
            throw new UsageException(name + ": cannot be read (" + unreadable.getMessage() + ")");
        }
    }
}
