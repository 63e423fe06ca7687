package masl.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * What installing makes so that a first run does not load its classes one by one: the class-data archive
 * of the build's JDK ({@code lib/masl.jsa}) and, where the build found a JDK 25 or later, the ahead-of-time
 * cache of that JDK ({@code lib/masl.aot}). The installed command ({@code installDist}) runs a mission
 * other than the one it was trained on, and the JVM's class-loading log says where the translator and
 * javac came from.
 */
@Tag("slow")
class InstalledArchivesTest {

    private static final Path INSTALLATION = Path.of(System.getProperty("masl.installation"));
    /** The JDK 25 or later the build made {@code masl.aot} with; empty when it found none. */
    private static final String AOT_JDK = System.getProperty("masl.aotJdk", "");

    @TempDir
    Path work;
    private Path mission;

    @Test
    void aFirstRunOnTheBuildsJdkMapsTheTranslatorAndJavacFromTheArchive() throws Exception {
        assertTrue(Files.isRegularFile(INSTALLATION.resolve("lib/masl.jsa")));
        List<String> loaded = firstRun(INSTALLATION, Map.of());
        // "(top)": the dynamic archive of the training run, on top of the JDK's own.
        assertTrue(loaded.contains("masl.translator.Translator source: shared objects file (top)"), () -> excerpt(loaded));
        assertTrue(loaded.contains("com.sun.tools.javac.main.JavaCompiler source: shared objects file (top)"),
                () -> excerpt(loaded));
    }

    @Test
    void withoutTheArchiveTheCommandRunsAsBefore() throws Exception {
        Path copy = work.resolve("masl");
        copyInstallation(copy);
        List<String> loaded = firstRun(copy, Map.of());
        assertTrue(loaded.stream().anyMatch(line -> line.startsWith("masl.translator.Translator source: file:")),
                () -> excerpt(loaded));
    }

    @Test
    void onTheJdk25TheBuildFoundAFirstRunMapsThemFromTheAheadOfTimeCache() throws Exception {
        if (AOT_JDK.isEmpty()) {
            assertFalse(Files.exists(INSTALLATION.resolve("lib/masl.aot")), "no JDK 25 was found, yet a cache was made");
            return;
        }
        assertTrue(Files.isRegularFile(INSTALLATION.resolve("lib/masl.aot")));
        List<String> loaded = firstRun(INSTALLATION, Map.of("MASL_JAVA_HOME", AOT_JDK));
        assertTrue(loaded.contains("masl.translator.Translator source: shared objects file"), () -> excerpt(loaded));
        assertTrue(loaded.contains("com.sun.tools.javac.main.JavaCompiler source: shared objects file"),
                () -> excerpt(loaded));
    }

    /** The classes a first run of the mission loaded, as "NAME source: WHERE", after checking its journal. */
    private List<String> firstRun(Path installation, Map<String, String> environment) throws Exception {
        Path log = work.resolve("class-load.log");
        ProcessBuilder builder = new ProcessBuilder(installation.resolve("bin/masl").toString(), "run", mission.toString());
        builder.environment().put("JAVA_HOME", System.getProperty("java.home"));
        builder.environment().remove("MASL_JAVA_HOME");
        builder.environment().remove("MASL_OPTS");
        builder.environment().put("JAVA_OPTS", "-Xlog:class+load:file=" + log + ":none");
        builder.environment().put("MASL_CACHE_DIR", Files.createTempDirectory(work, "cache").toString());
        builder.environment().putAll(environment);
        builder.redirectError(ProcessBuilder.Redirect.DISCARD);
        Process process = builder.start();
        String journal = new String(process.getInputStream().readAllBytes());
        assertTrue(process.waitFor(120, TimeUnit.SECONDS));
        assertEquals(0, process.exitValue(), journal);
        assertTrue(journal.startsWith("Hello again from agent "), journal);
        return Files.readAllLines(log);
    }

    private static String excerpt(List<String> loaded) {
        return String.join("\n", loaded.stream().filter(line -> line.contains("masl.translator.Translator ")
                || line.contains("javac.main.JavaCompiler ")).toList());
    }

    private static void copyInstallation(Path copy) throws IOException {
        for (String folder : List.of("bin", "lib")) {
            Files.createDirectories(copy.resolve(folder));
            try (Stream<Path> files = Files.list(INSTALLATION.resolve(folder))) {
                for (Path file : files.toList()) {
                    if (!file.getFileName().toString().startsWith("masl.")) {
                        Files.copy(file, copy.resolve(folder).resolve(file.getFileName()), StandardCopyOption.COPY_ATTRIBUTES);
                    }
                }
            }
        }
    }

    /** A mission the training run never saw: its generated classes cannot come from the archive. */
    @BeforeEach
    void writeMission() throws IOException {
        mission = work.resolve("greeting.masl");
        Files.writeString(mission, """
                import Default.xml as Default;
                Default dora = newAgent(Default);
                scalar entry main (true) {
                    .log("Hello again from agent ");
                    .logln(.getProxyID());
                }
                """);
    }
}
