package masl.cli;

import java.io.IOException;
import java.io.InputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import masl.runtime.MissionOutOfMemory;
import masl.runtime.descriptor.AgentPath;
import masl.translator.cache.CompiledMissionCache;
import masl.translator.compile.GeneratedCodeException;
import masl.translator.diagnostics.Suggestions;
import masl.translator.source.SourceFile;

/**
 * The {@code masl} command. Exit statuses (language reference §15): 0 success, 1 errors in the
 * program or its descriptors, 2 the mission failed (deadlock, crash, timeout, lost journal), 64 bad
 * usage, 70 an internal error (a bug of masl, reported as one, never as a stack trace), 71 out of
 * memory before a mission ran (translating a program too large for the heap), 74 an output that
 * cannot be written; a run Ctrl-C or SIGTERM stops ends with the JVM's 130 or 143 ({@link StopOnSignal}).
 */
public final class Masl {

    static final int OK = 0;
    static final int PROGRAM_ERRORS = 1;
    static final int MISSION_FAILED = 2;
    static final int USAGE = 64;
    static final int INTERNAL_ERROR = 70;
    /** sysexits' EX_OSERR: the JVM's heap is too small for the work, which is no bug of masl. */
    static final int OUT_OF_MEMORY = 71;
    /** sysexits' EX_IOERR: an output file or folder cannot be written. */
    static final int CANNOT_WRITE = 74;

    private final InputStream in;
    private final PrintStream out;
    private final PrintStream err;
    private final Progress.Settings progress;
    private final Map<String, String> environment;

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
        return new Masl(in, out, err, progress.quiet(true), environment);
    }

    /** @param environment the variables that choose the cache of compiled missions ({@code MASL_CACHE_DIR}, {@code XDG_CACHE_HOME}) */
    public Masl(InputStream in, PrintStream out, PrintStream err, Map<String, String> environment) {
        this(in, out, err, Progress.Settings.standard(), environment);
    }

    /** @param progress how long work is reported on {@code err} (tests give their own clock) */
    Masl(InputStream in, PrintStream out, PrintStream err, Progress.Settings progress) {
        this(in, out, err, progress, System.getenv());
    }

    private Masl(InputStream in, PrintStream out, PrintStream err, Progress.Settings progress, Map<String, String> environment) {
        this.in = in;
        this.out = out;
        this.err = err;
        this.progress = progress;
        this.environment = Map.copyOf(environment);
    }

    /**
     * The help asked for, or null if none was: {@code masl --help} (or {@code -h}, {@code help}) lists
     * every command; {@code masl help COMMAND}, or {@code --help}/{@code -h} among a command's words
     * whatever else they hold, shows that command's alone.
     */
    private static String helpAskedFor(String... args) throws UsageException {
        if (args.length == 0) {
            return null;
        }
        if (args[0].equals("help") && args.length > 1) {
            return Help.of(knownCommand(args[1]));
        }
        if (args[0].equals("help") || args[0].equals("--help") || args[0].equals("-h")) {
            return Help.all();
        }
        for (String arg : args) {
            if (arg.equals("--help") || arg.equals("-h")) {
                return Help.of(knownCommand(args[0]));
            }
        }
        return null;
    }

    /** {@code name} if it is a command, else bad usage, with the command it may be a slip for. */
    static String knownCommand(String name) throws UsageException {
        if (!Help.knows(name)) {
            throw new UsageException("unknown command '" + name + "'" + Suggestions.closest(name, Help.commands())
                    .map(command -> "; did you mean " + command + "?").orElse(""));
        }
        return name;
    }

    /** Runs one invocation and returns its exit status; never throws. */
    public int run(String... args) {
        try {
            String help = helpAskedFor(args);
            if (help != null) {
                out.print(help);
                return OK;
            }
            CommandLine line = CommandLine.parse(args);
            try (Progress shown = new Progress(err, progress.quiet(line.quiet))) {
                return dispatch(line, shown);
            }
        } catch (SourceFile.NotUtf8 notText) {
            err.println(notText.getMessage());
            return PROGRAM_ERRORS;
        } catch (UsageException usage) {
            err.println("masl: " + usage.getMessage());
            err.print(args.length == 0 ? Help.all() : Help.usageLine(args[0]));
            return USAGE;
        } catch (GeneratedCodeException bug) {
            err.println("masl: internal error: the Java generated for this program does not compile; please report it"
                    + " with the program" + savedReport(bug));
            return INTERNAL_ERROR;
        } catch (OutOfMemoryError exhausted) {
            return outOfMemory();
        } catch (RuntimeException | StackOverflowError | LinkageError bug) {
            if (causedByOutOfMemory(bug)) {
                return outOfMemory();
            }
            err.println("masl: internal error, please report it with the program that caused it: " + bug);
            return INTERNAL_ERROR;
        }
    }

    /**
     * The heap ran out before any mission did (a mission's own exhaustion fails it, status 2): the
     * program, or the trace drawn, is too large for the heap the JVM was given.
     */
    private int outOfMemory() {
        err.println("masl: out of memory: the heap's " + MissionOutOfMemory.heapLimitMiB() + " MiB is too small for"
                + " this input (java -Xmx, in JAVA_OPTS or MASL_OPTS, sets it)");
        return OUT_OF_MEMORY;
    }

    /** javac, run in memory, may report the heap's exhaustion wrapped in an exception of its own. */
    private static boolean causedByOutOfMemory(Throwable failure) {
        Throwable cause = failure.getCause();
        for (int depth = 0; cause != null && depth < 16; depth++, cause = cause.getCause()) {
            if (cause instanceof OutOfMemoryError) {
                return true;
            }
        }
        return false;
    }

    private int dispatch(CommandLine line, Progress progress) throws UsageException, SourceFile.NotUtf8 {
        return switch (line.command) {
            case "check" -> check(line, progress);
            case "compile" -> compile(line, progress);
            case "run" -> line.scenarioFile != null ? new SimRun(out, err, progress).run(line)
                    : new RunCommand(out, err, progress, cache())
                            .run(line, readProgram(line.singleFile()));
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

    /**
     * Reports the program's errors. A program without errors is left compiled in the cache of compiled
     * missions, as {@code run} leaves it, so that a check then a run translate and compile once; a
     * check of a program already there prints what its translation printed, without translating.
     */
    private int check(CommandLine line, Progress progress) throws UsageException, SourceFile.NotUtf8 {
        SourceFile source = readProgram(line.singleFile());
        AgentPath agentPath = AgentPath.parse(line.agentPath);
        boolean accepted = line.noCache ? Pipeline.load(source, agentPath, err, progress) != null
                : Pipeline.loadThroughCache(source, agentPath, err, progress, cache()) != null;
        return accepted ? OK : PROGRAM_ERRORS;
    }

    private CompiledMissionCache cache() {
        return new CompiledMissionCache(CompiledMissionCache.defaultFolder(environment));
    }

    private int compile(CommandLine line, Progress progress) throws UsageException, SourceFile.NotUtf8 {
        SourceFile source = readProgram(line.singleFile());
        if (line.outputFolder == null) {
            throw new UsageException("masl compile needs -d DIR, the folder to write the Java sources into");
        }
        AgentPath agentPath = AgentPath.parse(line.agentPath);
        Pipeline.Loaded loaded = Pipeline.load(source, agentPath, err, progress);
        if (loaded == null) {
            return PROGRAM_ERRORS;
        }
        Path folder;
        try {
            folder = Path.of(line.outputFolder);
        } catch (InvalidPathException bad) {
            throw new UsageException("not a folder name: " + line.outputFolder);
        }
        Map<Path, String> files = new LinkedHashMap<>();
        loaded.translation().javaSources().forEach((name, text) -> files.put(folder.resolve(name.replace('.', '/') + ".java"), text));
        CommandInputs inputs = CommandInputs.ofProgram(source, agentPath);
        for (Path file : files.keySet()) {
            inputs.refuseOverwriting("the Java source", file);
        }
        for (Map.Entry<Path, String> unit : files.entrySet()) {
            Path file = unit.getKey();
            try {
                Files.createDirectories(file.getParent());
                Files.writeString(file, unit.getValue());
            } catch (IOException cannotWrite) {
                err.println("masl: cannot write the Java source " + file + ": " + OutputFolder.reason(cannotWrite));
                return CANNOT_WRITE;
            }
        }
        return OK;
    }

    private static SourceFile readProgram(String name) throws UsageException, SourceFile.NotUtf8 {
        Path file;
        try {
            file = Path.of(name);
        } catch (InvalidPathException bad) {
            throw new UsageException("not a file name: " + name);
        }
        if (Files.isDirectory(file)) {
            throw new UsageException(name + ": is a folder, not a MASL program");
        }
        if (!Files.isRegularFile(file)) {
            throw new UsageException(name + ": no such file");
        }
        try {
            return SourceFile.read(file);
        } catch (SourceFile.NotUtf8 notText) {
            throw notText;
        } catch (IOException unreadable) {
            throw new UsageException(name + ": cannot be read (" + unreadable.getMessage() + ")");
        }
    }
}
