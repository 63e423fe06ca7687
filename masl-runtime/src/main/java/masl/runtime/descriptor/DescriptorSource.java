package masl.runtime.descriptor;

import java.io.IOException;
import java.io.InputStream;
import java.net.URI;
import java.net.URLConnection;
import java.nio.file.Path;
import java.util.Objects;
import java.util.Optional;

/**
 * Where a descriptor comes from: a file, an entry of a jar on the agent path, or a classpath resource.
 *
 * @param uri         the location, used to read it and as the identity of the loaded type
 * @param displayName how errors name it: the path as given, {@code lib/robots.jar!/Khepera.xml},
 *                    or {@code classpath:Default.xml}
 */
public record DescriptorSource(URI uri, String displayName) {

    public DescriptorSource {
        Objects.requireNonNull(uri, "uri");
        Objects.requireNonNull(displayName, "displayName");
    }

    /** A descriptor file; errors name it as {@code file} is written. */
    public static DescriptorSource ofFile(Path file) {
        return new DescriptorSource(file.toAbsolutePath().normalize().toUri(), file.toString());
    }

    /** The file, when the descriptor is a plain file (not inside a jar, not a packaged resource). */
    public Optional<Path> file() {
        return "file".equals(uri.getScheme()) ? Optional.of(Path.of(uri)) : Optional.empty();
    }

    /** The descriptor's file name, without folders: {@code Khepera.xml}. */
    public String fileName() {
        String location = uri.toString();
        return location.substring(location.lastIndexOf('/') + 1);
    }

    /** Opens the descriptor for reading; the caller closes the stream. */
    public InputStream open() throws IOException {
        URLConnection connection = uri.toURL().openConnection();
        // Jar URL caching would keep jar files open (and locked on some systems) after loading.
        connection.setUseCaches(false);
        return connection.getInputStream();
    }

    @Override
    public String toString() {
        return displayName;
    }
}
