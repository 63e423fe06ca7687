package masl.cli;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import masl.runtime.trace.JsonLinesTrace;
import masl.translator.diagnostics.Suggestions;

/**
 * The words of a {@code masl} invocation: a command, its operands and its options
 * ({@code --agent-path P} or {@code --agent-path=P}). Only options the command knows are accepted.
 */
final class CommandLine {

    /** The options each command accepts; those in {@link #FLAGS} take no value. */
    private static final Map<String, Set<String>> OPTIONS = Map.of(
            "check", Set.of("--agent-path", "--quiet", "--no-cache"),
            "compile", Set.of("--agent-path", "-d", "--quiet"),
            "run", Set.of("--agent-path", "--threads", "--quiet", "--seed", "--timeout", "--call-timeout", "--trace",
                    "--trace-limit", "--platform", "--main-host", "--main-port", "--sim", "--out", "--place", "--port",
                    "--deploy", "--secret-file", "--no-cache", "--local-host"),
            "container", Set.of("--agent-path", "--main-host", "--main-port", "--name", "--timeout", "--secret-file",
                    "--serve", "--local-host"),
            "timeline", Set.of("-o"),
            "lsp", Set.of("--agent-path"));
    /** A size: digits, then a unit K, M or G, with or without {@code iB} or {@code B}. */
    private static final Pattern SIZE = Pattern.compile("([0-9]+)(?i:([KMG])(?:i?B)?)?");
    private static final Set<String> FLAGS = Set.of("--threads", "--quiet", "--no-cache", "--serve");
    /**
     * The longest {@code --timeout}: ten years, within the nanosecond arithmetic of deadlines
     * ({@code Long.MAX_VALUE} ns is 292 years), and longer than any mission.
     */
    static final long MAX_TIMEOUT_SECONDS = 3650L * 24 * 60 * 60;

    final String command;
    final List<String> operands = new ArrayList<>();
    String agentPath = "";
    String outputFolder;
    String outputFile;
    boolean threads;
    /** No progress lines on standard error ({@link Progress}). */
    boolean quiet;
    boolean noCache;
    /** {@code masl container} serves one mission after another ({@code --serve}). */
    boolean serve;
    Long seed;
    Long timeoutSeconds;
    Long callTimeoutMillis;
    String traceFile;
    /** The size, in bytes, at which the trace is cut ({@code --trace-limit}); null if not given. */
    Long traceLimitGiven;
    String platform = "inproc";
    String mainHost;
    Integer mainPort;
    /** The address this JVM's JADE container binds to and is reached at ({@link LocalHost}); null: loopback. */
    String localHost;
    String scenarioFile;
    String place;
    String deploy;
    Integer port;
    String containerName;
    String secretFile;

    private CommandLine(String command) {
        this.command = command;
    }

    /** The size, in bytes, at which the trace is cut: {@code --trace-limit}'s, or the default. */
    long traceLimit() {
        return traceLimitGiven != null ? traceLimitGiven : JsonLinesTrace.DEFAULT_LIMIT;
    }

    /** The options {@code command} accepts. */
    static Set<String> optionsOf(String command) {
        return OPTIONS.get(command);
    }

    static CommandLine parse(String... args) throws UsageException {
        if (args.length == 0) {
            throw new UsageException("no command given");
        }
        CommandLine line = new CommandLine(Masl.knownCommand(args[0]));
        Set<String> known = OPTIONS.get(line.command);
        for (int i = 1; i < args.length; i++) {
            String arg = args[i];
            if (!arg.startsWith("-") || arg.equals("-")) {
                line.operands.add(arg);
                continue;
            }
            String name = arg.contains("=") ? arg.substring(0, arg.indexOf('=')) : arg;
            if (!known.contains(name)) {
                throw new UsageException("unknown option " + name + " for masl " + line.command + hint(name, known));
            }
            if (FLAGS.contains(name)) {
                if (arg.contains("=")) {
                    throw new UsageException(name + " takes no value");
                }
                if (name.equals("--threads")) {
                    line.threads = true;
                } else if (name.equals("--no-cache")) {
                    line.noCache = true;
                } else if (name.equals("--serve")) {
                    line.serve = true;
                } else {
                    line.quiet = true;
                }
                continue;
            }
            String value;
            if (arg.contains("=")) {
                value = arg.substring(arg.indexOf('=') + 1);
            } else if (i + 1 < args.length) {
                value = args[++i];
            } else {
                throw new UsageException(name + " needs a value");
            }
            line.set(name, value);
        }
        return line;
    }

    /** The option of the command {@code name} may be a slip for, or the commands {@code name} is an option of. */
    private static String hint(String name, Set<String> known) {
        Optional<String> near = Suggestions.closest(name, known.stream().sorted().toList());
        if (near.isPresent()) {
            return "; did you mean " + near.get() + "?";
        }
        List<String> others = OPTIONS.entrySet().stream().filter(command -> command.getValue().contains(name))
                .map(command -> "masl " + command.getKey()).sorted().toList();
        return others.isEmpty() ? "" : " (it is an option of " + String.join(", ", others) + ")";
    }

    private void set(String option, String value) throws UsageException {
        switch (option) {
            case "--agent-path" -> agentPath = value;
            case "-d", "--out" -> outputFolder = value;
            case "--sim" -> scenarioFile = value;
            case "-o" -> outputFile = value;
            case "--trace" -> traceFile = value;
            case "--trace-limit" -> traceLimitGiven = size(option, value, JsonLinesTrace.MIN_LIMIT);
            case "--seed" -> seed = number(option, value, Long.MIN_VALUE, Long.MAX_VALUE);
            case "--timeout" -> timeoutSeconds = number(option, value, 1, MAX_TIMEOUT_SECONDS);
            case "--call-timeout" -> callTimeoutMillis = number(option, value, 1, MAX_TIMEOUT_SECONDS * 1000);
            case "--platform" -> platform = oneOf(option, value, "inproc", "jade");
            case "--main-host" -> mainHost = value;
            case "--main-port" -> mainPort = port(option, value);
            case "--local-host" -> localHost = value;
            case "--port" -> port = port(option, value);
            case "--place" -> place = value;
            case "--deploy" -> deploy = value;
            case "--name" -> containerName = value;
            case "--secret-file" -> secretFile = value;
            default -> throw new UsageException("unknown option " + option);
        }
    }

    private static String oneOf(String option, String value, String... choices) throws UsageException {
        for (String choice : choices) {
            if (choice.equals(value)) {
                return value;
            }
        }
        throw new UsageException(option + " is one of " + String.join(", ", choices) + ", got '" + value + "'");
    }

    private static int port(String option, String value) throws UsageException {
        return (int) number(option, value, 1, 65535);
    }

    /**
     * A size in bytes: a whole number, or one followed by K, M or G (KiB, MiB, GiB: 1024, 1024², 1024³
     * bytes), as in {@code 512M}; at least {@code minimum}.
     */
    private static long size(String option, String value, long minimum) throws UsageException {
        Matcher size = SIZE.matcher(value);
        if (!size.matches()) {
            throw new UsageException(option + " needs a size in bytes, such as 1048576, 64K, 512M or 1G, got '" + value + "'");
        }
        int shift = switch (size.group(2) == null ? "" : size.group(2).substring(0, 1).toUpperCase(Locale.ROOT)) {
            case "K" -> 10;
            case "M" -> 20;
            case "G" -> 30;
            default -> 0;
        };
        long units = number(option, size.group(1), 0, Long.MAX_VALUE >> shift);
        long bytes = units << shift;
        if (bytes < minimum) {
            throw new UsageException(option + " must be at least " + minimum + " bytes, got " + value);
        }
        return bytes;
    }

    private static long number(String option, String value, long minimum, long maximum) throws UsageException {
        long number;
        try {
            number = Long.parseLong(value);
        } catch (NumberFormatException notANumber) {
            if (value.matches("[+-]?[0-9]+")) {
                throw new UsageException(option + " must be " + (value.startsWith("-") ? "at least " + minimum
                        : "at most " + maximum) + ", got " + value);
            }
            throw new UsageException(option + " needs a whole number, got '" + value + "'");
        }
        if (number < minimum) {
            throw new UsageException(option + " must be at least " + minimum + ", got " + value);
        }
        if (number > maximum) {
            throw new UsageException(option + " must be at most " + maximum + ", got " + value);
        }
        return number;
    }

    String singleFile() throws UsageException {
        if (operands.size() != 1) {
            throw new UsageException("masl " + command + " takes exactly one program file, got " + operands.size());
        }
        return operands.get(0);
    }
}
