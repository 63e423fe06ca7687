package masl.translator.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.Map;
import masl.runtime.descriptor.AgentPath;
import masl.translator.Frontend;
import masl.translator.diagnostics.DiagnosticPrinter;
import masl.translator.source.SourceFile;

/**
 * The {@code masl} command. Exit statuses (components.md): 0 success, 1 errors in the program or its
 * descriptors, 64 bad usage, 70 an internal error (a bug of masl, reported as one, never as a stack trace).
 */
public final class Masl {

    static final int OK = 0;
    static final int PROGRAM_ERRORS = 1;
    static final int USAGE = 64;
    static final int INTERNAL_ERROR = 70;

    static final String USAGE_TEXT = """
            usage: masl check FILE [--agent-path PATH]
              check   report every error of a MASL program and of the descriptors it imports
            options:
              --agent-path PATH   folders and jars holding agent descriptors and their classes, ':'-separated;
                                  searched after the program's folder, before the descriptors masl ships
            exit status: 0 no error, 1 errors in the program or its descriptors, 64 bad usage
            """;

    private final PrintStream out;
    private final PrintStream err;

    public Masl(PrintStream out, PrintStream err) {
        this.out = out;
        this.err = err;
    }

    /** Runs one invocation and returns its exit status; never throws. */
    public int run(String... args) {
        try {
            if (args.length == 1 && (args[0].equals("--help") || args[0].equals("-h") || args[0].equals("help"))) {
                out.print(USAGE_TEXT);
                return OK;
            }
            CommandLine line = CommandLine.parse(args);
            return switch (line.command) {
                case "check" -> check(line);
                default -> throw new UsageException("unknown command '" + line.command + "'");
            };
        } catch (UsageException usage) {
            err.println("masl: " + usage.getMessage());
            err.print(USAGE_TEXT);
            return USAGE;
        } catch (RuntimeException | StackOverflowError | OutOfMemoryError bug) {
            err.println("masl: internal error, please report it with the program that caused it: " + bug);
            return INTERNAL_ERROR;
        }
    }

    private int check(CommandLine line) throws UsageException {
        SourceFile source = readProgram(line.singleFile());
        Frontend.Result result = new Frontend(AgentPath.parse(line.agentPath)).analyse(source);
        new DiagnosticPrinter(Map.of(source.name(), source.text())).print(result.diagnostics().sorted(), err);
        return result.succeeded() ? OK : PROGRAM_ERRORS;
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
