package masl.jade.placement;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;
import masl.runtime.diagnostic.Diagnostic;

/**
 * Which container runs each deployed agent's program ({@code masl run --deploy}): {@code a=c2,b=c3};
 * {@code *} stands for every agent the option does not name, the placement does not place and no
 * external FIPA agent stands behind (its program runs here, its primitives are that agent's), and
 * {@code +} spreads those agents over several containers in turn, in declaration order:
 * {@code *=c2+c3} deploys the whole team over two containers. Agents not deployed run in the
 * coordinator's JVM. A mistake is reported with its position ({@code --deploy:1:7: error: …}).
 */
public final class Deployment {

    private static final Pattern NAME = Pattern.compile("[A-Za-z_$][A-Za-z0-9_$]*");
    private static final Pattern CONTAINER = Pattern.compile("[A-Za-z0-9_.-]+");
    private static final String WHERE = "--deploy";

    private Deployment() {
    }

    /**
     * The container of each deployed agent, in declaration order.
     *
     * @param declared the program's agents, in declaration order
     * @param placed the agents whose bodies {@code --place} puts elsewhere: their programs stay here
     * @param external the agents whose primitives an external FIPA agent answers (a type with
     *     {@code <Fipa>}): their programs stay here too
     * @throws IllegalArgumentException positioned, for a malformed pair, an agent named twice, an agent
     *     the program does not declare, one that is also placed or external, or several containers
     *     for one agent
     */
    public static Map<String, String> parse(String option, List<String> declared, Set<String> placed,
            Set<String> external) {
        Map<String, String> named = new LinkedHashMap<>();
        List<String> spread = null;
        int column = 1;
        for (String pair : option.split(",", -1)) {
            int at = column + pair.length() - pair.stripLeading().length();
            String text = pair.strip();
            int equals = text.indexOf('=');
            if (equals < 0) {
                throw error(at, "expected AGENT=CONTAINER or *=CONTAINER+CONTAINER, got '" + text + "'");
            }
            String agent = text.substring(0, equals).strip();
            List<String> containers = containers(text.substring(equals + 1), at + equals + 1);
            if (agent.equals("*")) {
                if (spread != null) {
                    throw error(at, "* is given twice");
                }
                spread = containers;
            } else {
                checkAgent(agent, at, declared, placed, external);
                if (containers.size() > 1) {
                    throw error(at + equals + 1, agent + " is one agent: give it one container, or spread * over several");
                }
                if (named.putIfAbsent(agent, containers.get(0)) != null) {
                    throw error(at, agent + " is deployed twice");
                }
            }
            column += pair.length() + 1;
        }
        Map<String, String> deployment = new LinkedHashMap<>();
        int turn = 0;
        for (String agent : declared) {
            if (named.containsKey(agent)) {
                deployment.put(agent, named.get(agent));
            } else if (spread != null && !placed.contains(agent) && !external.contains(agent)) {
                deployment.put(agent, spread.get(turn++ % spread.size()));
            }
        }
        return deployment;
    }

    private static List<String> containers(String text, int column) {
        List<String> containers = new ArrayList<>();
        int at = column;
        for (String part : text.split("\\+", -1)) {
            String container = part.strip();
            if (!CONTAINER.matcher(container).matches()) {
                throw error(at + part.length() - part.stripLeading().length(), "'" + container
                        + "' is not a container name (letters, digits, '_', '.', '-')");
            }
            containers.add(container);
            at += part.length() + 1;
        }
        return containers;
    }

    private static void checkAgent(String agent, int column, List<String> declared, Set<String> placed,
            Set<String> external) {
        if (!NAME.matcher(agent).matches()) {
            throw error(column, "'" + agent + "' is not an agent name (or *)");
        }
        if (!declared.contains(agent)) {
            throw error(column, agent + " is not an agent of the program (it declares " + String.join(", ", declared) + ")");
        }
        if (placed.contains(agent)) {
            throw error(column, agent + " is placed with --place: its program runs here, its body there; deploy it"
                    + " or place it, not both");
        }
        if (external.contains(agent)) {
            throw error(column, agent + " stands for an external FIPA agent (its type has <Fipa>): its program runs"
                    + " here, its primitives are that agent's; it cannot be deployed");
        }
    }

    private static IllegalArgumentException error(int column, String message) {
        return new IllegalArgumentException(Diagnostic.error(WHERE, 1, column, message).headline());
    }

    /** The containers a deployment uses, in order of first use. */
    public static List<String> containersOf(Map<String, String> deployment) {
        return deployment.values().stream().distinct().toList();
    }
}
