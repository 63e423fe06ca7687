package masl.runtime.descriptor;

import java.io.File;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.MalformedURLException;
import java.net.URI;
import java.net.URISyntaxException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Enumeration;
import java.util.List;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;
import java.util.stream.Stream;

/**
 * Where descriptors and the implementation classes they name are looked up (MASL §4, components.md
 * "Agent path"): an ordered list of folders and jars, followed by the descriptors shipped with the
 * project as classpath resources (the {@code agents} module puts {@code Default.xml} at the root).
 * Entries that do not exist are skipped, as a Java class path does. Immutable.
 */
public final class AgentPath {

    private final List<Path> entries;
    private final ClassLoader resources;

    private AgentPath(List<Path> entries, ClassLoader resources) {
        this.entries = List.copyOf(entries);
        this.resources = Objects.requireNonNull(resources, "resources");
    }

    /**
     * Parses a path such as {@code "robots:lib/arm.jar"}, separated by the platform's path separator
     * ({@code :} on Unix); empty elements are ignored. Shipped descriptors are looked up through the
     * thread's context class loader (or this class's loader when there is none).
     */
    public static AgentPath parse(String path) {
        List<Path> entries = new ArrayList<>();
        for (String element : path.split(File.pathSeparator)) {
            if (!element.isBlank()) {
                entries.add(Path.of(element));
            }
        }
        return new AgentPath(entries, defaultResources());
    }

    /** An agent path of {@code entries}, with the shipped descriptors looked up through {@code resources}. */
    public static AgentPath of(List<Path> entries, ClassLoader resources) {
        return new AgentPath(entries, resources);
    }

    /**
     * This path with {@code folder} searched first (a program's folder, where its descriptors are looked
     * up before the agent path); this path itself when {@code folder} is null.
     */
    public AgentPath withFirst(Path folder) {
        if (folder == null) {
            return this;
        }
        List<Path> first = new ArrayList<>(List.of(folder));
        first.addAll(entries);
        return new AgentPath(first, resources);
    }

    /** The folders and jars, in lookup order. */
    public List<Path> entries() {
        return entries;
    }

    /** The class loader whose resources are the shipped descriptors. */
    public ClassLoader resources() {
        return resources;
    }

    /**
     * Finds descriptor {@code fileName} (may contain {@code /}-separated folders; an absolute path is
     * taken as it is): relative to {@code programDir} first (when not null), then in each entry in
     * order, then among the classpath resources.
     *
     * @throws UncheckedIOException if a jar on the path cannot be read
     */
    public Optional<DescriptorSource> find(String fileName, Path programDir) {
        return findAll(fileName, programDir).stream().findFirst();
    }

    /**
     * Where {@link #find} looks, in its order, for a message: {@code "the program's folder robots,
     * the agent path (lib, arm.jar) and the descriptors shipped with masl"}.
     */
    public String describeLookup(Path programDir) {
        List<String> places = new ArrayList<>();
        if (programDir != null) {
            places.add("the program's folder " + programDir);
        }
        if (!entries.isEmpty()) {
            places.add("the agent path (" + String.join(", ", entries.stream().map(Path::toString).toList()) + ")");
        }
        places.add("the descriptors shipped with masl");
        return places.size() == 1 ? places.get(0)
                : String.join(", ", places.subList(0, places.size() - 1)) + " and " + places.get(places.size() - 1);
    }

    /**
     * The descriptors {@link #find} could have found instead of {@code fileName}: those in the same
     * folder as it would be (its folder part, {@code robots/} in {@code robots/Kepera.xml}) in the
     * program's folder, the path's folders and jars, and the folder or jar that holds the shipped
     * {@code Default.xml}, each named as it would be written. For hints; a place that cannot be read
     * adds nothing.
     */
    public Set<String> descriptorNames(String fileName, Path programDir) {
        int slash = fileName.replace(File.separatorChar, '/').lastIndexOf('/');
        String folder = slash < 0 ? "" : fileName.substring(0, slash + 1);
        Set<String> names = new TreeSet<>();
        List<Path> places = new ArrayList<>();
        if (programDir != null) {
            places.add(programDir);
        }
        places.addAll(entries);
        shippedPlace().ifPresent(places::add);
        for (Path place : places) {
            try {
                if (Files.isDirectory(place.resolve(folder))) {
                    xmlFilesIn(place.resolve(folder)).forEach(source -> names.add(folder + nameOf(source.uri())));
                } else if (Files.isRegularFile(place)) {
                    xmlEntriesOf(place).stream().map(source -> source.uri().toString())
                            .map(uri -> uri.substring(uri.indexOf("!/") + 2))
                            .filter(entry -> entry.startsWith(folder) && entry.indexOf('/', folder.length()) < 0)
                            .forEach(names::add);
                }
            } catch (UncheckedIOException | InvalidPathException unreadable) {
                // a hint is a courtesy: a place that cannot be read only gives fewer candidates
            }
        }
        return names;
    }

    /** The folder or jar the shipped {@code Default.xml} comes from, if it is a file or a jar. */
    private Optional<Path> shippedPlace() {
        URL shipped = resources.getResource("Default.xml");
        if (shipped == null) {
            return Optional.empty();
        }
        String text = shipped.toString();
        try {
            if (text.startsWith("jar:file:")) {
                return Optional.of(Path.of(URI.create(text.substring("jar:".length(), text.indexOf("!/")))));
            }
            if (text.startsWith("file:")) {
                return Optional.of(Path.of(shipped.toURI()).getParent());
            }
        } catch (URISyntaxException | IllegalArgumentException unusual) {
            return Optional.empty();
        }
        return Optional.empty();
    }

    private static String nameOf(URI location) {
        String text = location.toString();
        return text.substring(text.lastIndexOf('/') + 1);
    }

    /**
     * A class loader over the folders and jars of this path, delegating to {@code parent} first;
     * it loads the implementation classes of users' agent types.
     */
    public ClassLoader classLoader(ClassLoader parent) {
        URL[] urls = entries.stream().map(AgentPath::toUrl).toArray(URL[]::new);
        return new URLClassLoader(urls, parent);
    }

    /** Every descriptor named {@code fileName}, in the order of {@link #find}. */
    List<DescriptorSource> findAll(String fileName, Path programDir) {
        List<DescriptorSource> found = new ArrayList<>();
        Path asPath = Path.of(fileName);
        if (asPath.isAbsolute()) {
            if (Files.isRegularFile(asPath)) {
                found.add(DescriptorSource.ofFile(asPath));
            }
            return found;
        }
        if (programDir != null) {
            fileIn(programDir, fileName).ifPresent(found::add);
        }
        for (Path entry : entries) {
            (Files.isDirectory(entry) ? fileIn(entry, fileName) : jarEntry(entry, fileName)).ifPresent(found::add);
        }
        String resourceName = fileName.replace(File.separatorChar, '/');
        URL resource = resources.getResource(resourceName);
        if (resource != null) {
            found.add(new DescriptorSource(toUri(resource), "classpath:" + resourceName));
        }
        return found;
    }

    /**
     * Every {@code .xml} file in the entries: folders searched recursively, jars entirely. Classpath
     * resources cannot be listed, so they are not part of it.
     */
    List<DescriptorSource> allDescriptorsInEntries() {
        List<DescriptorSource> found = new ArrayList<>();
        for (Path entry : entries) {
            if (Files.isDirectory(entry)) {
                found.addAll(xmlFilesUnder(entry));
            } else if (Files.isRegularFile(entry)) {
                found.addAll(xmlEntriesOf(entry));
            }
        }
        return found;
    }

    /** The {@code .xml} files directly in {@code folder} (not below it), sorted by name. */
    static List<DescriptorSource> xmlFilesIn(Path folder) {
        try (Stream<Path> files = Files.list(folder)) {
            return files.filter(AgentPath::isXmlFile).sorted().map(DescriptorSource::ofFile).toList();
        } catch (IOException e) {
            throw new UncheckedIOException("cannot list " + folder, e);
        }
    }

    private static List<DescriptorSource> xmlFilesUnder(Path folder) {
        try (Stream<Path> files = Files.walk(folder)) {
            return files.filter(AgentPath::isXmlFile).sorted().map(DescriptorSource::ofFile).toList();
        } catch (IOException e) {
            throw new UncheckedIOException("cannot list " + folder, e);
        }
    }

    private static boolean isXmlFile(Path file) {
        return Files.isRegularFile(file) && file.getFileName().toString().endsWith(".xml");
    }

    private static List<DescriptorSource> xmlEntriesOf(Path jar) {
        List<DescriptorSource> found = new ArrayList<>();
        try (JarFile jarFile = new JarFile(jar.toFile())) {
            Enumeration<JarEntry> jarEntries = jarFile.entries();
            while (jarEntries.hasMoreElements()) {
                JarEntry jarEntry = jarEntries.nextElement();
                if (!jarEntry.isDirectory() && jarEntry.getName().endsWith(".xml")) {
                    found.add(jarSource(jar, jarEntry.getName()));
                }
            }
            return found;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read jar " + jar, e);
        }
    }

    private static Optional<DescriptorSource> fileIn(Path folder, String fileName) {
        Path file = folder.resolve(fileName);
        return Files.isRegularFile(file) ? Optional.of(DescriptorSource.ofFile(file)) : Optional.empty();
    }

    private static Optional<DescriptorSource> jarEntry(Path jar, String fileName) {
        if (!Files.isRegularFile(jar)) {
            return Optional.empty();
        }
        String entryName = fileName.replace(File.separatorChar, '/');
        try (JarFile jarFile = new JarFile(jar.toFile())) {
            JarEntry entry = jarFile.getJarEntry(entryName);
            return entry == null || entry.isDirectory() ? Optional.empty() : Optional.of(jarSource(jar, entryName));
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read jar " + jar, e);
        }
    }

    private static DescriptorSource jarSource(Path jar, String entryName) {
        URI uri = URI.create("jar:" + jar.toAbsolutePath().normalize().toUri() + "!/" + entryName);
        return new DescriptorSource(uri, jar + "!/" + entryName);
    }

    private static ClassLoader defaultResources() {
        ClassLoader context = Thread.currentThread().getContextClassLoader();
        return context != null ? context : AgentPath.class.getClassLoader();
    }

    private static URL toUrl(Path entry) {
        try {
            return entry.toAbsolutePath().normalize().toUri().toURL();
        } catch (MalformedURLException e) {
            throw new IllegalArgumentException("agent path entry " + entry + " is not a valid location", e);
        }
    }

    private static URI toUri(URL url) {
        try {
            return url.toURI();
        } catch (URISyntaxException e) {
            throw new IllegalStateException("class loader returned an invalid resource URL " + url, e);
        }
    }

    @Override
    public String toString() {
        return String.join(File.pathSeparator, entries.stream().map(Path::toString).toList());
    }
}
