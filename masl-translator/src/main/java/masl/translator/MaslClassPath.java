package masl.translator;

import java.io.File;
import java.net.URISyntaxException;
import java.security.CodeSource;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import masl.runtime.MissionProgram;

/**
 * Where masl's own runtime and shipped agents were loaded from. Generated code compiles against
 * them; they are on the JVM's class path when masl runs as a command, but not when it runs inside
 * another program's class loader (the Gradle plug-in in a build's JVM), so they are named explicitly.
 */
public final class MaslClassPath {

    private static final String SHIPPED_AGENT_CLASS = "masl.agents.Default";

    private MaslClassPath() {
    }

    /** The jars or class folders of the runtime and the shipped agents (when they are present). */
    public static List<String> runtimeAndShippedAgents() {
        Set<String> locations = new LinkedHashSet<>();
        locationOf(MissionProgram.class).ifPresent(locations::add);
        try {
            locationOf(Class.forName(SHIPPED_AGENT_CLASS, false, MaslClassPath.class.getClassLoader())).ifPresent(locations::add);
        } catch (ClassNotFoundException notShipped) {
            // A launcher without the agents module: descriptors then name classes of the agent path only.
        }
        return List.copyOf(locations);
    }

    /** The jar or class folder {@code type} was loaded from, when it is a file. */
    public static Optional<String> locationOf(Class<?> type) {
        CodeSource source = type.getProtectionDomain().getCodeSource();
        if (source == null || source.getLocation() == null) {
            return Optional.empty();
        }
        try {
            return Optional.of(new File(source.getLocation().toURI()).getPath());
        } catch (URISyntaxException | IllegalArgumentException notAFile) {
            return Optional.empty();
        }
    }
}
