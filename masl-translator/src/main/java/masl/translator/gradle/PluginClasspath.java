package masl.translator.gradle;

import java.io.File;
import java.net.URISyntaxException;
import java.security.CodeSource;
import java.util.LinkedHashSet;
import java.util.Set;

/**
 * Where the plug-in's own copy of the runtime and of the shipped agents lives: generated code is
 * compiled against them, so a project that applies the plug-in needs no other MASL dependency.
 */
final class PluginClasspath {

    private static final String RUNTIME_CLASS = "masl.runtime.MissionProgram";
    private static final String SHIPPED_AGENT_CLASS = "masl.agents.Default";

    private PluginClasspath() {
    }

    /** The jars or class folders holding the runtime and the shipped agents (one entry when they coincide). */
    static Set<File> runtimeAndShippedAgents() {
        Set<File> locations = new LinkedHashSet<>();
        locations.add(locationOf(RUNTIME_CLASS));
        locations.add(locationOf(SHIPPED_AGENT_CLASS));
        return locations;
    }

    private static File locationOf(String className) {
        try {
            Class<?> type = Class.forName(className, false, PluginClasspath.class.getClassLoader());
            CodeSource source = type.getProtectionDomain().getCodeSource();
            if (source == null) {
                throw new IllegalStateException("the masl plug-in cannot locate " + className);
            }
            return new File(source.getLocation().toURI());
        } catch (ClassNotFoundException | URISyntaxException missing) {
            throw new IllegalStateException("the masl plug-in's class path lacks " + className, missing);
        }
    }
}
