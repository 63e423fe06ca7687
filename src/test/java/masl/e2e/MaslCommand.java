package masl.e2e;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import masl.cli.Masl;

/**
 * One run of the {@code masl} command in this process: its exit status, standard output and standard
 * error, without progress lines (so standard error holds the diagnostics alone however slow the machine).
 */
record MaslCommand(int status, String out, String err) {

    static MaslCommand run(String... arguments) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = new Masl(new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8)).withoutProgress().run(arguments);
        return new MaslCommand(status, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
    }

    @Override
    public String toString() {
        return "status " + status + "\nstdout:\n" + out + "stderr:\n" + err;
    }
}
