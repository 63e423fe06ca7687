package masl.cli;

import java.io.InputStream;
import java.io.PrintStream;
import masl.lsp.MaslLsp;
import masl.runtime.descriptor.AgentPath;

/**
 * {@code masl lsp}: the language server for editors (masl-lsp), speaking LSP on standard input and output
 * until the editor ends the session.
 */
final class LspCommand {

    private final InputStream in;
    private final PrintStream protocol;
    private final PrintStream err;

    LspCommand(InputStream in, PrintStream protocol, PrintStream err) {
        this.in = in;
        this.protocol = protocol;
        this.err = err;
    }

    int run(CommandLine line) throws UsageException {
        if (!line.operands.isEmpty()) {
            throw new UsageException("masl lsp takes no file: the editor sends the programs it opens");
        }
        AgentPath agentPath = AgentPath.parse(line.agentPath);
        // The protocol owns the output stream: anything else printed while serving (an agent class's static
        // initializer, run when a descriptor's implementation is checked) goes to the error stream instead.
        PrintStream previous = System.out;
        System.setOut(err);
        try {
            return MaslLsp.serve(in, protocol, agentPath);
        } catch (InterruptedException interrupted) {
            Thread.currentThread().interrupt();
            return Masl.INTERNAL_ERROR;
        } finally {
            System.setOut(previous);
        }
    }
}
