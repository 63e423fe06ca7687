package masl.cli;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

/**
 * What {@code masl} says about itself: {@code masl --help} (every command, every option),
 * {@code masl COMMAND --help} (that command only), and the one line of usage that follows a
 * mistake on the command line. Each command's usage and each option's text are written once here,
 * and both helps are put together from them.
 */
final class Help {

    /** One command: its usage lines (after {@code usage: }), what it does, the options it takes. */
    private record Command(String usage, String shortUsage, String description, List<String> options) {
    }

    private static final String INDENT = "       ";

    private static final Map<String, Command> COMMANDS = new LinkedHashMap<>();
    private static final Map<String, String> OPTIONS = new LinkedHashMap<>();

    static {
        COMMANDS.put("run", new Command("""
                masl run FILE [--agent-path PATH] [--threads | --seed N] [--timeout SECONDS] [--trace FILE] [--quiet]
                        [--trace-limit SIZE] [--call-timeout MS] [--platform inproc|jade] [--no-cache]
                        [--main-host HOST --main-port PORT | --port PORT] [--local-host ADDRESS]
                        [--place AGENT=CONTAINER,... | --place FILE] [--deploy AGENT=CONTAINER,...]
                        [--secret-file FILE]
                masl run --sim SCENARIO [--out DIR] [--seed N] [--timeout SECONDS] [--agent-path PATH] [--quiet]
                        [--trace-limit SIZE]
                """, "masl run FILE [OPTION]... | masl run --sim SCENARIO [OPTION]...", """
                translate a MASL program, compile it in memory and run its mission in this process;
                the journal (and only the journal) goes to standard output
                with --sim, the mission the scenario names runs on its simulated robots; trajectories,
                events, trace, journal and a picture go to --out (default: NAME.out beside NAME.scenario.xml)
                """, List.of("--agent-path", "--threads", "--seed", "--timeout", "--call-timeout", "--trace", "--trace-limit",
                "--no-cache", "--quiet", "--platform", "--main-host", "--port", "--local-host", "--place", "--deploy", "--secret-file", "--sim",
                "--out")));
        COMMANDS.put("container", new Command("""
                masl container --main-host HOST --main-port PORT --name CONTAINER [--agent-path PATH]
                        [--timeout SECONDS] [--secret-file FILE] [--serve] [--local-host ADDRESS]
                """, "masl container --main-host HOST --main-port PORT --name CONTAINER [OPTION]...", """
                join a JADE platform as container CONTAINER and host the bodies (the primitives) of the
                agents a run --place puts there, their programs running in the run's JVM; and run the
                programs of the agents a run --deploy puts there, translated here; ends with the mission,
                or with --serve serves the next one
                """, List.of("--main-host", "--name", "--agent-path", "--timeout", "--secret-file", "--serve",
                "--local-host")));
        COMMANDS.put("compile", new Command("""
                masl compile FILE -d DIR [--agent-path PATH] [--quiet]
                """, null, """
                translate a MASL program into Java sources under DIR (one folder per package)
                """, List.of("-d", "--agent-path", "--quiet")));
        COMMANDS.put("check", new Command("""
                masl check FILE [--agent-path PATH] [--quiet] [--no-cache]
                """, null, """
                report every error of a MASL program and of the descriptors it imports: all that
                compile and run would report, as they translate and compile it, without running it;
                a program without errors is left compiled in the cache, for the next run
                """, List.of("--agent-path", "--no-cache", "--quiet")));
        COMMANDS.put("timeline", new Command("""
                masl timeline TRACE -o FILE.html
                """, null, """
                draw a trace written by run --trace (or run --sim) as a self-contained HTML page: one
                lane per agent over time, coloured by block, with barrier trips, waves, invocations,
                events and failures; zoom, pan and filter it in a browser
                """, List.of("-o")));
        COMMANDS.put("lsp", new Command("""
                masl lsp [--agent-path PATH]
                """, null, """
                serve the Language Server Protocol on standard input and output for an editor: the
                diagnostics of check on every change, completion, hover, go to definition, outline
                """, List.of("--agent-path")));

        OPTIONS.put("--agent-path", """
                --agent-path PATH   folders and jars holding agent descriptors and their classes, ':'-separated;
                                    searched after the program's folder, before the descriptors masl ships
                """);
        OPTIONS.put("--threads", """
                --threads           run each agent on a thread of its own instead of a small pool
                """);
        OPTIONS.put("--seed", """
                --seed N            run on one thread, every scheduling choice drawn from seed N (replayable);
                                    with --sim, the physics seed instead of the scenario's
                """);
        OPTIONS.put("--timeout", """
                --timeout SECONDS   stop the mission after SECONDS (default: no limit); for container, stop
                                    waiting for the mission's end after SECONDS (with --serve: for each mission)
                """);
        OPTIONS.put("--call-timeout", """
                --call-timeout MS   a primitive running longer than MS milliseconds gives its caller its default
                                    value and the event timeout; the mission goes on (default: no limit); with
                                    --platform jade it also bounds each FIPA agent's call from outside the mission
                                    (default for those: 10000); with --seed, MS of the seeded run's virtual clock
                """);
        OPTIONS.put("--trace", """
                --trace FILE        write the trace (one JSON object per line) to FILE
                """);
        OPTIONS.put("--trace-limit", """
                --trace-limit SIZE  cut the trace (with --sim, its trace.jsonl) at SIZE bytes (K, M, G: KiB, MiB,
                                    GiB; default 1G): its last record is then {"event":"trace-cut","limit":BYTES},
                                    the run goes on; a trace that cannot be written fails the run
                """);
        OPTIONS.put("--no-cache", """
                --no-cache          translate and compile the program even if an earlier run or check of the same
                                    program, descriptors, agent path, masl and JDK left it compiled in the cache
                                    ($MASL_CACHE_DIR, else $XDG_CACHE_HOME/masl, else ~/.cache/masl), and
                                    leave nothing there
                """);
        OPTIONS.put("--quiet", """
                --quiet             no progress on standard error: by default, work running longer than a second
                                    (translating, compiling, a --sim run: simulated time, real-time factor,
                                    journal lines) is shown there, on one line rewritten on a terminal
                """);
        OPTIONS.put("--platform", """
                --platform P        inproc (default): run in this process; jade: run inside a JADE platform,
                                    one JADE agent per MASL agent, registered with the DF, answering FIPA requests
                """);
        OPTIONS.put("--main-host", """
                --main-host HOST, --main-port PORT
                                    with --platform jade: join the platform whose main container listens there
                                    instead of starting one on loopback; for container, the platform to join
                """);
        OPTIONS.put("--port", """
                --port PORT         with --platform jade: the port of the main container run starts (default: a free one)
                """);
        OPTIONS.put("--local-host", """
                --local-host ADDRESS
                                    with --platform jade (and for container): the address of this machine the
                                    JVM's container listens on and is reached at by the others (default:
                                    127.0.0.1, only this machine); needed to join a main container on another one
                """);
        OPTIONS.put("--place", """
                --place AGENT=CONTAINER,... or FILE (lines AGENT=CONTAINER)
                                    with --platform jade: run these agents' bodies in the containers named (started
                                    with masl container), their programs in this JVM; other agents stay here
                """);
        OPTIONS.put("--deploy", """
                --deploy AGENT=CONTAINER,... (*=C1+C2: every agent not named, spread over C1, C2 in turn)
                                    with --platform jade: run these agents' programs in the containers named
                                    (masl container), which translate the program themselves; the mission's
                                    blocks, barriers, shared variables and events stay in this JVM; * leaves
                                    out placed agents and those external FIPA agents (<Fipa>) stand for
                """);
        OPTIONS.put("--secret-file", """
                --secret-file FILE  with --place or --deploy (and for masl container): where run writes a fresh secret for the
                                    mission (a new owner-only file, deleted at its end; an existing file is refused)
                                    and its containers read it; they obey only messages signed with it
                                    (default: .masl-mission-secret-PORT in this folder, PORT the main container's)
                """);
        OPTIONS.put("--sim", """
                --sim SCENARIO      run the mission the scenario (NAME.scenario.xml) names on its simulated robots
                """);
        OPTIONS.put("--out", """
                --out DIR           with --sim: where trajectories, events, trace, journal and picture go
                """);
        OPTIONS.put("--serve", """
                --serve             for container: once a mission ended, join the platform of the next one
                                    at the same address (a new masl run, a new secret in --secret-file)
                                    and serve it too, until stopped
                """);
        OPTIONS.put("--name", """
                --name CONTAINER    the name the container takes on the platform, as --place names it
                """);
        OPTIONS.put("-d", """
                -d DIR              the folder the Java sources are written into
                """);
        OPTIONS.put("-o", """
                -o FILE.html        the page to write
                """);
    }

    private static final String EXIT_STATUS = """
            exit status: 0 success, 1 errors in the program or its descriptors, 2 the mission failed,
                         deadlocked or timed out, or its journal or trace could not be written, 64 bad usage,
                         70 internal error, 71 out of memory before the mission ran, 74 an output could
                         not be written, 130 or 143 stopped by Ctrl-C or SIGTERM
            """;

    private Help() {
    }

    static boolean knows(String command) {
        return COMMANDS.containsKey(command);
    }

    static List<String> commands() {
        return List.copyOf(COMMANDS.keySet());
    }

    /** {@code masl --help}: every command's usage and what it does, every option, the exit statuses. */
    static String all() {
        String usages = COMMANDS.values().stream().map(Command::usage).collect(Collectors.joining());
        StringBuilder text = new StringBuilder(usage(usages)).append("commands:\n");
        COMMANDS.forEach((name, command) -> text.append(described(name, command.description())));
        text.append("options:\n");
        OPTIONS.values().forEach(option -> text.append(prefixed(option, "  ")));
        return text.append(EXIT_STATUS)
                .append("masl COMMAND --help (or masl help COMMAND) shows the help of that command alone\n").toString();
    }

    /** {@code masl COMMAND --help}: its usage, what it does, its options, the exit statuses. */
    static String of(String name) {
        Command command = COMMANDS.get(name);
        StringBuilder text = new StringBuilder(usage(command.usage())).append(prefixed(command.description(), "  "))
                .append("options:\n");
        command.options().forEach(option -> text.append(prefixed(OPTIONS.get(option), "  ")));
        return text.append(EXIT_STATUS).toString();
    }

    /**
     * The one line of usage that follows a mistake on the command line: the command's (the list of
     * commands if {@code name} is none), and where the rest is.
     */
    static String usageLine(String name) {
        Command command = COMMANDS.get(name);
        if (command == null) {
            return "usage: masl COMMAND [ARGUMENT]... (commands: " + String.join(", ", COMMANDS.keySet())
                    + "; masl --help describes them)\n";
        }
        String usage = command.shortUsage() != null ? command.shortUsage() : command.usage().strip();
        return "usage: " + usage + " (masl " + name + " --help for more)\n";
    }

    /** {@code usage: } and the usage lines, each after the first aligned under the first. */
    private static String usage(String lines) {
        return "usage: " + prefixed(lines, INDENT).substring(INDENT.length());
    }

    private static String prefixed(String text, String prefix) {
        return text.lines().map(line -> prefix + line + "\n").collect(Collectors.joining());
    }

    /** A command's name and what it does, in two columns. */
    private static String described(String name, String description) {
        List<String> lines = description.lines().toList();
        StringBuilder text = new StringBuilder("  %-10s%s\n".formatted(name, lines.get(0)));
        lines.subList(1, lines.size()).forEach(line -> text.append(" ".repeat(12)).append(line).append('\n'));
        return text.toString();
    }
}
