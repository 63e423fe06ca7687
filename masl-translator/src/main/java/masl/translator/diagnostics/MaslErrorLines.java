package masl.translator.diagnostics;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.Charset;
import java.util.ArrayList;
import java.util.List;

/**
 * The standard error of {@code masl run}, passed on as it comes and read on the way for why the
 * run failed: the first diagnostic of a program with errors ({@code file:line:col: error: …}), or
 * masl's own last word on the mission ({@code masl: the mission deadlocked…}) with the failure it
 * names on the line below. Only the first lines are kept, enough for either. The build plug-ins,
 * which start {@code masl run} in a JVM of their own, say with it why their task or goal failed.
 */
public final class MaslErrorLines extends OutputStream {

    private static final int KEPT_LINES = 500;
    private static final String MASL = "masl: ";
    private static final String REPLAY = MASL + "the same run again";

    private final OutputStream passedOn;
    private final ByteArrayOutputStream line = new ByteArrayOutputStream();
    private final List<String> lines = new ArrayList<>();

    public MaslErrorLines(OutputStream passedOn) {
        this.passedOn = passedOn;
    }

    @Override
    public void write(int b) throws IOException {
        passedOn.write(b);
        if (b == '\n') {
            endLine();
        } else if (lines.size() < KEPT_LINES) {
            line.write(b);
        }
    }

    @Override
    public void flush() throws IOException {
        passedOn.flush();
    }

    private void endLine() {
        if (lines.size() < KEPT_LINES) {
            lines.add(line.toString(Charset.defaultCharset()).stripTrailing());
        }
        line.reset();
    }

    /** Why masl says the run failed; empty when it said nothing recognisable. */
    public String why() {
        if (line.size() > 0) {
            endLine();
        }
        for (String error : lines) {
            if (error.contains(": error: ")) {
                return error;
            }
        }
        for (int i = lines.size() - 1; i >= 0; i--) {
            String said = lines.get(i);
            if (said.startsWith(MASL) && !said.startsWith(REPLAY)) {
                String failure = i + 1 < lines.size() && lines.get(i + 1).startsWith("  ") ? ": " + lines.get(i + 1).strip() : "";
                return said.substring(MASL.length()) + failure;
            }
        }
        return "";
    }
}
