package masl.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CyclicBarrier;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.stream.Stream;
import masl.cli.CheckCommandTest.Run;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The cache of compiled missions of {@code masl run} and {@code masl check}: an unchanged program
 * runs from it, a checked program too, a changed program or descriptor never runs a stale entry, a
 * tampered entry is not run, and masl processes writing the same entry at once leave one that runs.
 */
@Timeout(60)
class RunCacheTest {

    private static final String PROGRAM = """
            import Scout.xml as Scout;
            Scout a, b = newAgent(Scout);
            scalar entry main (true) { .logln("Hello from the cache"); }
            """;

    @TempDir
    Path folder;

    private Path cache() {
        return folder.resolve("cache");
    }

    private Run run(String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        InputStream noInput = new ByteArrayInputStream(new byte[0]);
        Masl masl = new Masl(noInput, new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8), Map.of("MASL_CACHE_DIR", cache().toString()));
        int status = masl.withoutProgress().run(args);
        return new Run(status, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
    }

    /** A program importing Scout.xml, its own copy of the root descriptor, from its folder. */
    private String program(String text) throws IOException {
        Path file = folder.resolve("scout.masl");
        Files.writeString(file, text);
        return file.toString();
    }

    private void writeScout(String rootDescriptorEdit) throws IOException {
        String root;
        try (InputStream shipped = RunCacheTest.class.getClassLoader().getResourceAsStream("Default.xml")) {
            root = new String(shipped.readAllBytes(), StandardCharsets.UTF_8);
        }
        String scout = root.replace("short_class_name=\"Default\"", "short_class_name=\"Scout\"");
        Files.writeString(folder.resolve("Scout.xml"), rootDescriptorEdit == null ? scout
                : scout.replaceAll(rootDescriptorEdit, ""));
    }

    private List<Path> entries() throws IOException {
        if (!Files.isDirectory(cache())) {
            return List.of();
        }
        try (Stream<Path> files = Files.list(cache())) {
            return files.filter(file -> file.toString().endsWith(".mission")).sorted().toList();
        }
    }

    /** The file's identity: a rewritten entry is a new file renamed into place. */
    private static Object identity(Path file) throws IOException {
        BasicFileAttributes attributes = Files.readAttributes(file, BasicFileAttributes.class);
        return List.of(String.valueOf(attributes.fileKey()), attributes.lastModifiedTime());
    }

    @Test
    void aSecondRunOfAnUnchangedProgramRunsTheEntryOfTheFirst() throws IOException {
        writeScout(null);
        String program = program(PROGRAM);
        assertEquals(new Run(0, "Hello from the cache\n", ""), run("run", program));
        List<Path> entries = entries();
        assertEquals(1, entries.size());
        Object written = identity(entries.get(0));
        assertEquals(new Run(0, "Hello from the cache\n", ""), run("run", program));
        assertEquals(entries, entries());
        assertEquals(written, identity(entries.get(0)), "the entry was not used but written again");
    }

    @Test
    void aChangedProgramIsTranslatedAgain() throws IOException {
        writeScout(null);
        assertEquals(new Run(0, "Hello from the cache\n", ""), run("run", program(PROGRAM)));
        String changed = program(PROGRAM.replace("Hello from the cache", "Hello again"));
        assertEquals(new Run(0, "Hello again\n", ""), run("run", changed));
        assertEquals(2, entries().size());
    }

    @Test
    void aChangedDescriptorIsReadAgainAndItsErrorsReported() throws IOException {
        writeScout(null);
        String program = program(PROGRAM);
        assertEquals(new Run(0, "Hello from the cache\n", ""), run("run", program));
        writeScout("(?s)<Primitive function_name=\"logln\".*?</Primitive>");
        Run stale = run("run", program);
        assertEquals(1, stale.status(), stale.toString());
        assertTrue(stale.err().contains("scout.masl:3:29: error: cannot find primitive logln"), stale.err());
        assertEquals(stale, run("check", program), "a check found what the change broke otherwise than a run");
    }

    @Test
    void aDescriptorThatAppearsEarlierOnTheLookupIsUsed() throws IOException {
        String program = program(PROGRAM.replace("Scout.xml", "robots/Scout.xml"));
        Path robots = Files.createDirectories(folder.resolve("lib/robots"));
        writeScout(null);
        Files.move(folder.resolve("Scout.xml"), robots.resolve("Scout.xml"));
        assertEquals(new Run(0, "Hello from the cache\n", ""), run("run", program, "--agent-path", folder.resolve("lib").toString()));
        // robots/Scout.xml beside the program now comes first (MASL §4), and it lacks logln.
        writeScout("(?s)<Primitive function_name=\"logln\".*?</Primitive>");
        Files.createDirectories(folder.resolve("robots"));
        Files.move(folder.resolve("Scout.xml"), folder.resolve("robots/Scout.xml"));
        Run shadowed = run("run", program, "--agent-path", folder.resolve("lib").toString());
        assertEquals(1, shadowed.status(), shadowed.toString());
    }

    @Test
    void aTamperedEntryIsNotRunButReplaced() throws IOException {
        writeScout(null);
        String program = program(PROGRAM);
        run("run", program);
        Path entry = entries().get(0);
        byte[] bytes = Files.readAllBytes(entry);
        String text = new String(bytes, StandardCharsets.ISO_8859_1);
        int constant = text.indexOf("Hello from the cache");
        assertTrue(constant > 0, "the entry holds the class files");
        bytes[constant] = 'J';
        Files.write(entry, bytes);
        Object tampered = identity(entry);
        assertEquals(new Run(0, "Hello from the cache\n", ""), run("run", program));
        assertNotEquals(tampered, identity(entry), "the tampered entry was left in place");
        assertEquals(new Run(0, "Hello from the cache\n", ""), run("run", program));
    }

    @Test
    void runsWritingTheSameEntryAtOnceLeaveOneThatRuns() throws Exception {
        writeScout(null);
        String program = program(PROGRAM);
        int processes = 4;
        CyclicBarrier start = new CyclicBarrier(processes);
        ExecutorService pool = Executors.newFixedThreadPool(processes);
        try {
            List<Future<Run>> runs = new ArrayList<>();
            for (int i = 0; i < processes; i++) {
                runs.add(pool.submit(() -> {
                    start.await();
                    return run("run", program);
                }));
            }
            for (Future<Run> each : runs) {
                assertEquals(new Run(0, "Hello from the cache\n", ""), each.get());
            }
        } finally {
            pool.shutdownNow();
        }
        assertEquals(1, entries().size());
        try (Stream<Path> files = Files.list(cache())) {
            assertEquals(1, files.count(), "a temporary file was left behind");
        }
        Object written = identity(entries().get(0));
        assertEquals(new Run(0, "Hello from the cache\n", ""), run("run", program));
        assertEquals(written, identity(entries().get(0)));
    }

    @Test
    void aCheckLeavesTheProgramCompiledForTheRunAfterIt() throws IOException {
        writeScout(null);
        String program = program(PROGRAM);
        assertEquals(new Run(0, "", ""), run("check", program));
        List<Path> entries = entries();
        assertEquals(1, entries.size(), "the check left nothing for the run");
        Object written = identity(entries.get(0));
        assertEquals(new Run(0, "Hello from the cache\n", ""), run("run", program));
        assertEquals(written, identity(entries().get(0)), "the run compiled the program again");
        assertEquals(new Run(0, "", ""), run("check", program));
        assertEquals(written, identity(entries().get(0)), "the second check compiled the program again");
    }

    @Test
    void aCheckOfAProgramWithErrorsReportsThemEachTimeAndLeavesNothing() throws IOException {
        writeScout(null);
        String program = program(PROGRAM.replace(".logln(", ".loglnn("));
        Run first = run("check", program);
        assertEquals(1, first.status(), first.toString());
        assertTrue(first.err().contains("scout.masl:3:29: error: cannot find primitive loglnn"), first.err());
        assertEquals(first, run("check", program));
        assertEquals(List.of(), entries());
    }

    @Test
    void noCacheNeitherReadsNorWritesIt() throws IOException {
        writeScout(null);
        assertEquals(new Run(0, "Hello from the cache\n", ""), run("run", "--no-cache", program(PROGRAM)));
        assertEquals(new Run(0, "", ""), run("check", "--no-cache", program(PROGRAM)));
        assertEquals(List.of(), entries());
    }

    @Test
    void aCacheFolderOthersCanWriteIsNotUsed() throws IOException {
        writeScout(null);
        Files.createDirectories(cache());
        Files.setPosixFilePermissions(cache(), PosixFilePermissions.fromString("rwxrwxrwx"));
        Run run = run("run", program(PROGRAM));
        assertEquals(0, run.status());
        assertEquals("Hello from the cache\n", run.out());
        assertTrue(run.err().startsWith("masl: not using the cache of compiled missions: "), run.err());
        assertTrue(run.err().contains("can be written by other users"), run.err());
        assertEquals(List.of(), entries());
    }

    /**
     * The owner and permissions checked are the cache folder's own: a symbolic link there (to a folder
     * of this user's, here, but it could be anyone's) is refused, whatever it points to.
     */
    @Test
    void aCacheFolderThatIsASymbolicLinkIsNotUsed() throws IOException {
        writeScout(null);
        Path elsewhere = Files.createDirectory(folder.resolve("elsewhere"), PosixFilePermissions.asFileAttribute(
                PosixFilePermissions.fromString("rwx------")));
        Files.createSymbolicLink(cache(), elsewhere);
        Run run = run("run", program(PROGRAM));
        assertEquals(0, run.status());
        assertEquals("Hello from the cache\n", run.out());
        assertEquals("masl: not using the cache of compiled missions: " + cache()
                + " is a symbolic link, not a folder of its own\n", run.err());
        try (Stream<Path> written = Files.list(elsewhere)) {
            assertEquals(List.of(), written.toList());
        }
    }
}
