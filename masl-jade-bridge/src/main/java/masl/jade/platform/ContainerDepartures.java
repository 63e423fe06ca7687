package masl.jade.platform;

import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A container that left the platform abruptly (its JVM killed or ended without leaving), in masl's
 * words: one line per container, {@code masl: container c9 left the platform (…)}, instead of what
 * JADE says of it on the main container's standard error, in its log ({@code EOF reached}, then
 * {@code --- Node <c9> UNREACHABLE ---}) or with {@code printStackTrace} when its AMS removes the
 * container twice ({@code jade.core.NotFoundException: No container named c9 was found.}, JADE 4.3's words), and
 * when the platform's shutdown cannot end it ({@code Cannot kill container c9: Unreachable.}). Every
 * coordinator hears of such a departure, a body's container as an outside agents' one; the bodies'
 * calls that now fail are said by the coordinator itself ({@code Distribution}). Uses no JADE class:
 * the {@code masl} command passes its standard error through it.
 */
public final class ContainerDepartures {

    private static final Pattern UNREACHABLE = Pattern.compile("--- Node <(.+)> UNREACHABLE ---");
    private static final Pattern REMOVED_TWICE = Pattern.compile(
            "jade\\.core\\.NotFoundException: No container named (\\S+) was found\\.?");
    /**
     * What JADE 4.3's AMS logs when its platform's shutdown reaches a container it has not removed
     * yet: after that container's departure, a line that only accompanies it.
     */
    private static final Pattern NOT_KILLED = Pattern.compile("Cannot kill container (\\S+): Unreachable\\.?");
    /** What JADE's connection reader logs when a peer's connection ends: the departure says it. */
    private static final String CONNECTION_ENDED = "EOF reached";

    /** The containers whose departure was said, in this JVM. */
    private static final Set<String> SAID = ConcurrentHashMap.newKeySet();

    private ContainerDepartures() {
    }

    /**
     * What to print instead of JADE's line {@code text} (a log record's message, or a line printed
     * on standard error), if it tells of a departure: the departure's line, the first time a
     * container's is met, else {@code ""} (said already, or a line that only accompanies a
     * departure). Empty for any other line, printed as it is.
     */
    public static Optional<String> inMaslWords(String text) {
        String line = text.strip();
        if (line.equals(CONNECTION_ENDED)) {
            return Optional.of("");
        }
        Matcher notKilled = NOT_KILLED.matcher(line);
        if (notKilled.matches()) {
            // Of a container not known to have left (the main container's own, in a failed shutdown), JADE's words stand.
            return SAID.contains(notKilled.group(1)) ? Optional.of("") : Optional.empty();
        }
        Matcher departed = UNREACHABLE.matcher(line);
        if (!departed.matches()) {
            departed = REMOVED_TWICE.matcher(line);
            if (!departed.matches()) {
                return Optional.empty();
            }
        }
        return Optional.of(said(departed.group(1)) ? "" : line(departed.group(1)));
    }

    /** Whether the departure of {@code container} was said already; from now on it is. */
    public static boolean said(String container) {
        return !SAID.add(container);
    }

    private static String line(String container) {
        return "masl: container " + container + " left the platform (its JVM ended or its connection broke)";
    }
}
