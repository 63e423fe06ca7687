package masl.translator.cli;

import java.util.ArrayList;
import java.util.List;

/**
 * The words of a {@code masl} invocation: a command, its operands and its options
 * ({@code --agent-path P} or {@code --agent-path=P}). Only options the command knows are accepted.
 */
final class CommandLine {

    final String command;
    final List<String> operands = new ArrayList<>();
    String agentPath = "";

    private CommandLine(String command) {
        this.command = command;
    }

    static CommandLine parse(String... args) throws UsageException {
        if (args.length == 0) {
            throw new UsageException("no command given");
        }
        CommandLine line = new CommandLine(args[0]);
        for (int i = 1; i < args.length; i++) {
            String arg = args[i];
            if (arg.equals("--agent-path")) {
                if (i + 1 == args.length) {
                    throw new UsageException("--agent-path needs a value: folders and jars separated by ':'");
                }
                line.agentPath = args[++i];
            } else if (arg.startsWith("--agent-path=")) {
                line.agentPath = arg.substring("--agent-path=".length());
            } else if (arg.startsWith("-") && arg.length() > 1) {
                throw new UsageException("unknown option " + arg);
            } else {
                line.operands.add(arg);
            }
        }
        return line;
    }

    String singleFile() throws UsageException {
        if (operands.size() != 1) {
            throw new UsageException("masl " + command + " takes exactly one program file, got " + operands.size());
        }
        return operands.get(0);
    }
}
