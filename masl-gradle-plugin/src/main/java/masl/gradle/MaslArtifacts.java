package masl.gradle;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.Properties;

/**
 * The coordinates of the modules the plug-in adds to a build: those of its own version, written into
 * its jar by its build ({@code masl/gradle/artifacts.properties}), so that the plug-in, the runtime the
 * generated code runs on and the command {@code maslRun} starts always match.
 */
final class MaslArtifacts {

    private static final String RESOURCE = "artifacts.properties";

    private final Properties properties;
    private final String group;
    private final String version;

    private MaslArtifacts(Properties properties) {
        this.properties = properties;
        this.group = required(properties, "group");
        this.version = required(properties, "version");
    }

    static MaslArtifacts ofThisPlugin() {
        try (InputStream in = MaslArtifacts.class.getResourceAsStream(RESOURCE)) {
            if (in == null) {
                throw new IllegalStateException("the masl plug-in's jar lacks masl/gradle/" + RESOURCE);
            }
            Properties properties = new Properties();
            properties.load(in);
            return new MaslArtifacts(properties);
        } catch (IOException unreadable) {
            throw new UncheckedIOException("cannot read masl/gradle/" + RESOURCE, unreadable);
        }
    }

    /** {@code group:module:version} of a MASL module, e.g. {@code masl-cli}. */
    String module(String name) {
        return group + ":" + name + ":" + version;
    }

    String group() {
        return group;
    }

    /** {@code group:module:version} of a JUnit Platform module of the version masl-testing is built with. */
    String junitPlatform(String name) {
        return "org.junit.platform:" + name + ":" + required(properties, "junitPlatform");
    }

    private static String required(Properties properties, String key) {
        String value = properties.getProperty(key);
        if (value == null || value.isBlank()) {
            throw new IllegalStateException("masl/gradle/" + RESOURCE + " has no " + key);
        }
        return value;
    }
}
