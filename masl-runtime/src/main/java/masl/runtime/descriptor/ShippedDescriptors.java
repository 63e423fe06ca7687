package masl.runtime.descriptor;

import java.net.URL;
import java.security.CodeSource;

/**
 * The descriptors in the jar of masl's own agent types ({@code masl.agents}): the agents module's tests
 * validate every one of them against the schema when masl is built, so a translation reads them
 * without compiling the schema again (most of a fresh JVM's first load). Only a jar counts, never a
 * folder a user could edit.
 */
final class ShippedDescriptors {

    /** {@code jar:file:/…/agents-<version>.jar!/}, or null when the shipped types come from no jar. */
    private static final String JAR = shippedJar();

    private ShippedDescriptors() {
    }

    static boolean contains(DescriptorSource source) {
        return JAR != null && source.uri().toString().startsWith(JAR);
    }

    private static String shippedJar() {
        try {
            Class<?> root = Class.forName(DescriptorLoader.ROOT_TYPE, false, ShippedDescriptors.class.getClassLoader());
            CodeSource code = root.getProtectionDomain().getCodeSource();
            URL location = code == null ? null : code.getLocation();
            return location != null && location.toString().endsWith(".jar") ? "jar:" + location + "!/" : null;
        } catch (ClassNotFoundException | SecurityException notShipped) {
            return null;
        }
    }
}
