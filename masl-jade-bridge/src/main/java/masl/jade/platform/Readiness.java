package masl.jade.platform;

import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The one line {@code masl run --platform jade} and {@code masl container} print on standard error when
 * another JVM may rely on them, so that it knows when and where to join without polling. The format is
 * stable (fields in this order, separated by one space, values without spaces):
 *
 * <pre>
 * masl: platform ready: host=127.0.0.1 port=41234 platform=127.0.0.1:41234/JADE
 * masl: container ready: name=c2 host=127.0.0.1 port=41234 platform=127.0.0.1:41234/JADE agents=b,d
 * </pre>
 *
 * The first says the platform accepts containers at {@code host}:{@code port} (its main container's
 * address, also when {@code masl run} joined a platform rather than starting one); the second that the
 * container {@code name} of that platform hosts the bodies of {@code agents} (in placement order).
 * {@link #parse} reads either.
 */
public record Readiness(Optional<String> container, String host, int port, String platform, List<String> agents) {

    private static final Pattern LINE = Pattern.compile(
            "masl: (?:platform ready:|container ready: name=(\\S+)) host=(\\S+) port=(\\d{1,5}) platform=(\\S+)"
                    + "(?: agents=(\\S*))?");

    /** The line of a platform that accepts containers. */
    public static String platform(JadePlatform platform) {
        return "masl: platform ready: " + address(platform);
    }

    /** The line of a container whose bodies are placed. */
    public static String container(String name, JadePlatform platform, List<String> agents) {
        return "masl: container ready: name=" + name + " " + address(platform) + " agents=" + String.join(",", agents);
    }

    private static String address(JadePlatform platform) {
        return "host=" + platform.mainHost() + " port=" + platform.mainPort() + " platform=" + platform.platformName();
    }

    /** The readiness a line states; empty if the line is not one (a platform line has no container nor agents). */
    public static Optional<Readiness> parse(String line) {
        Matcher matcher = LINE.matcher(line);
        if (!matcher.matches() || (matcher.group(1) == null) != (matcher.group(5) == null)) {
            return Optional.empty();
        }
        List<String> agents = matcher.group(5) == null || matcher.group(5).isEmpty() ? List.of()
                : Arrays.asList(matcher.group(5).split(","));
        return Optional.of(new Readiness(Optional.ofNullable(matcher.group(1)), matcher.group(2),
                Integer.parseInt(matcher.group(3)), matcher.group(4), List.copyOf(agents)));
    }
}
