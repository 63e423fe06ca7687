package masl.cli;

import java.io.PrintStream;
import java.util.regex.Pattern;

/**
 * Where JADE's own notices go during a {@code --platform jade} run: standard error, since standard
 * output is the journal's alone. JADE 4.3 prints them with {@code System.out.println}. One of them,
 * {@code Agent NAME interrupted while waiting}, says only that an agent's thread was interrupted while
 * its JADE agent was being deleted, which masl does to each of its agents once the mission has ended:
 * it reports nothing the user can act on, and comes or not with the threads' timing, so it is dropped.
 * Every other line reaches standard error as JADE wrote it.
 */
final class JadeNotices extends PrintStream {

    /** JADE's words ({@code jade.core.Agent.waitUntilWake}): "Agent " + getName() + " interrupted while waiting". */
    private static final Pattern INTERRUPTED_IN_DELETION = Pattern.compile("Agent \\S+ interrupted while waiting");

    JadeNotices(PrintStream standardError) {
        super(standardError, true);
    }

    @Override
    public void println(String line) {
        if (line == null || !INTERRUPTED_IN_DELETION.matcher(line).matches()) {
            super.println(line);
        }
    }
}
