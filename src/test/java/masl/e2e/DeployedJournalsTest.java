package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.function.Consumer;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import masl.cli.Main;
import masl.e2e.ManualPage.CodeBlock;
import masl.jade.platform.JadeThreads;
import masl.testing.jade.SecondJvm;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.TestFactory;
import org.junit.jupiter.api.Timeout;

/**
 * Every program of examples.md (E1–E8), the manual's examples of events, countermeasures, labels
 * and permeability (language.md §8–§11), and the missions that need no robot, with every agent's
 * program deployed over two containers in two other JVMs, as a robot team runs them: {@code masl
 * container --serve --name c2} and {@code c3}, started once and serving one mission after another,
 * and {@code masl run --platform jade --deploy '*=c2+c3'} in this JVM for each mission. Each gives
 * the journal it gives in-process ({@code masl run} alone, in this JVM too): the same text where
 * the program makes it deterministic, the same lines with the program's own constraints where it
 * lets its agents interleave; a few run again and again. Each container says it is ready with the
 * agents deployed on it and that they ended, mission after mission, without being restarted.
 */
@Timeout(900)
@Tag("slow")
class DeployedJournalsTest {

    /** How often the programs whose journal depends most on the order of coordination messages run. */
    private static final int REPEATS = 2;
    private static final Path MANUAL = Path.of("docs/manual/language.md");
    /** The manual's sections whose examples run deployed: events, primitives (countermeasures), labels, permeability. */
    private static final List<String> SECTIONS = List.of("## 8. ", "## 9. ", "## 10. ", "## 11. ");

    private static Path folder;
    private static Path secretFile;
    private static int port;
    private static SecondJvm c2;
    private static SecondJvm c3;

    /** What of a deployed journal is the in-process one's. */
    private enum Same {
        /** The text: the program makes it deterministic. */
        TEXT,
        /** The lines, in any order: the program lets its agents interleave. */
        LINES,
        /** Only what the constraint asks: the program lets the mission choose what is written. */
        CONSTRAINT
    }

    /**
     * A program, how its journal compares with the in-process one, what else every journal of it must
     * show, and what the containers must say of its deployed run.
     */
    private record Program(Path file, Same same, Consumer<List<String>> constraint, Consumer<Deployed> containers) {

        Program(Path file, Same same, Consumer<List<String>> constraint) {
            this(file, same, constraint, deployed -> { });
        }

        Program(Path file, Same same) {
            this(file, same, lines -> { });
        }

        @Override
        public String toString() {
            return file.getFileName().toString();
        }
    }

    @BeforeAll
    static void startServingContainers() throws IOException {
        folder = Files.createTempDirectory("masl-deployed-journals");
        ManualExamples.of(ManualPage.read(MANUAL), folder).get(0).verify().run();
        secretFile = folder.resolve("secret");
        port = freePort();
        c2 = container("c2");
        c3 = container("c3");
    }

    @AfterAll
    static void stopContainers() throws IOException {
        try (SecondJvm second = c2; SecondJvm third = c3) {
            // Closed even if the other fails to.
        } finally {
            deleteFolder(folder);
        }
    }

    /**
     * Each program once, then again and again those whose journal depends most on the order in which
     * coordination messages arrive: lock-step with shared variables, an event emitted in one container
     * and reacted to in both, a locked block's waves, a wave that thins out.
     */
    @TestFactory
    Stream<DynamicTest> everyProgramGivesItsInProcessJournalDeployed() throws IOException {
        List<Program> programs = new ArrayList<>(examples());
        programs.addAll(manualExamples());
        programs.addAll(missions());
        List<DynamicTest> runs = new ArrayList<>();
        for (Program program : programs) {
            runs.add(DynamicTest.dynamicTest(program.toString(), () -> assertSameJournal(program)));
        }
        for (Program program : List.of(programs.get(1), programs.get(3), programs.get(5), programs.get(6))) {
            for (int run = 2; run <= REPEATS; run++) {
                runs.add(DynamicTest.dynamicTest(program + ", run " + run, () -> assertSameJournal(program)));
            }
        }
        return runs.stream();
    }

    private static List<Program> examples() {
        return List.of(
                new Program(example("e1_scalar_main.masl"), Same.TEXT),
                // Lock-step with shared variables.
                new Program(example("e2_shared_and_local.masl"), Same.TEXT,
                        lines -> assertEquals(List.of("n=5", "mine=1", "mine=1", "mine=1", "mine=1", "mine=1"), lines)),
                new Program(example("e3_asynchronous_child.masl"), Same.TEXT),
                // An event emitted in one container and reacted to in the parent.
                new Program(example("e4_events.masl"), Same.LINES, lines -> {
                    assertEquals("heard now", lines.get(0));
                    assertEquals(List.of("heard now", "heard now", "heard now", "heard now", "worker 1", "worker 2", "worker 3"),
                            lines.stream().sorted().toList());
                }),
                // An invocation denied by the callee's state in the other container; each container says
                // which agents it runs and that they ended, missions after the first on the same containers.
                new Program(example("e5_permeability.masl"), Same.TEXT, lines -> assertEquals(List.of("timeout", "seen=0"), lines),
                        DeployedJournalsTest::eachContainerSaysWhichAgentsItRan),
                new Program(example("e6_one_at_a_time.masl"), Same.TEXT),
                new Program(example("e7_reelect.masl"), Same.LINES),
                new Program(example("e8_break_out_of_two.masl"), Same.LINES, lines -> assertEquals("in", lines.get(0))));
    }

    private static Path example(String name) {
        return Path.of("src/test/resources/examples", name);
    }

    /**
     * The programs of the manual's sections on events, primitives, labels and permeability that show a
     * journal, each written to the folder the page's files (descriptors, compiled Java) are in.
     */
    private static List<Program> manualExamples() throws IOException {
        List<String> lines = Files.readAllLines(MANUAL);
        List<CodeBlock> blocks = ManualPage.read(MANUAL).blocks();
        List<Program> programs = new ArrayList<>();
        for (int i = 0; i + 1 < blocks.size(); i++) {
            CodeBlock block = blocks.get(i);
            CodeBlock journal = blocks.get(i + 1);
            if (block.language().equals("masl") && block.words().isEmpty() && !block.attributes().containsKey("file")
                    && journal.language().equals("journal") && inSections(lines, block.line())) {
                Path file = Files.writeString(folder.resolve("language-" + block.line() + ".masl"), block.text());
                programs.add(new Program(file, journal.words().contains("any-order") ? Same.LINES : Same.TEXT));
            }
        }
        return programs;
    }

    /** Whether line {@code line} (1-based) of the page is in one of {@link #SECTIONS}. */
    private static boolean inSections(List<String> page, int line) {
        for (int i = line - 1; i >= 0; i--) {
            String text = page.get(i);
            if (text.startsWith("## ")) {
                return SECTIONS.stream().anyMatch(text::startsWith);
            }
        }
        return false;
    }

    /**
     * The missions of {@code missions/} that need no simulation and no agent other than MASL's.
     */
    private static List<Program> missions() {
        // Which agent runs the scalar main is the mission's choice, in-process as deployed.
        return List.of(new Program(Path.of("missions/hello.masl"), Same.CONSTRAINT, lines -> assertTrue(
                lines.size() == 1 && Pattern.matches("Hello from agent [0-2]", lines.get(0)), lines.toString())),
                // Each robot stores its report in its element of a shared array, which one of them reads out.
                new Program(Path.of("missions/mixed-team.masl"), Same.TEXT, lines -> assertEquals(3, lines.size(),
                        lines.toString())));
    }

    private static void assertSameJournal(Program program) throws Exception {
        MaslCommand inProcess = MaslCommand.run("run", program.file().toString(), "--agent-path", folder.toString(),
                "--timeout", "60");
        assertEquals(0, inProcess.status(), program + " in-process: " + inProcess);
        Deployed deployed = deployed(program.file());
        String why = program + "\nin-process:\n" + inProcess.out() + "deployed:\n" + deployed;
        switch (program.same()) {
            case TEXT -> assertEquals(inProcess.out(), deployed.journal(), why);
            case LINES -> assertEquals(inProcess.out().lines().sorted().toList(),
                    deployed.journal().lines().sorted().toList(), why);
            case CONSTRAINT -> { }
        }
        try {
            program.constraint().accept(inProcess.out().lines().toList());
            program.constraint().accept(deployed.journal().lines().toList());
            program.containers().accept(deployed);
        } catch (AssertionError broken) {
            throw new AssertionError(why, broken);
        }
    }

    /** e5's agents: {@code a} deployed on c2, {@code b} on c3, each said ready and ended by its container. */
    private static void eachContainerSaysWhichAgentsItRan(Deployed e5) {
        assertTrue(e5.c2().lines().anyMatch(line -> line.startsWith("masl: container ready: name=c2 ")
                && line.endsWith(" agents=a")), e5.c2());
        assertTrue(e5.c3().lines().anyMatch(line -> line.startsWith("masl: container ready: name=c3 ")
                && line.endsWith(" agents=b")), e5.c3());
        assertTrue(e5.c2().contains("masl-ended hosted a\n"), e5.c2());
        assertTrue(e5.c3().contains("masl-ended hosted b\n"), e5.c3());
    }

    /** One deployed run: its journal, and what each container printed during it. */
    private record Deployed(String journal, String c2, String c3) {
        @Override
        public String toString() {
            return journal + "c2:\n" + c2 + "c3:\n" + c3;
        }
    }

    private static Deployed deployed(Path program) throws Exception {
        int c2Before = c2.output().length();
        int c3Before = c3.output().length();
        MaslCommand run = MaslCommand.run("run", program.toString(), "--agent-path", folder.toString(), "--platform",
                "jade", "--port", String.valueOf(port), "--deploy", "*=c2+c3", "--timeout", "60", "--secret-file",
                secretFile.toString());
        String c2Output = c2.output().substring(c2Before);
        String c3Output = c3.output().substring(c3Before);
        String why = program + ": " + run + "\nc2:\n" + c2Output + "c3:\n" + c3Output;
        // masl says where its platform is, and nothing else; JADE may add notices of its own as it shuts down.
        assertEquals(List.of("masl: platform ready: host=127.0.0.1 port=" + port + " platform=127.0.0.1:" + port + "/JADE"),
                run.err().lines().filter(line -> line.startsWith("masl:")).toList(), why);
        assertEquals(0, run.status(), why);
        assertEquals(List.of(), JadeThreads.live(), "JADE threads left in this JVM after the mission");
        assertFalse(Files.exists(secretFile), "the mission's secret outlived it");
        return new Deployed(run.out(), c2Output, c3Output);
    }

    private static SecondJvm container(String name) throws IOException {
        return SecondJvm.start(Main.class, "container", "--serve", "--main-host", "127.0.0.1", "--main-port",
                String.valueOf(port), "--name", name, "--agent-path", folder.toString(), "--timeout", "120",
                "--secret-file", secretFile.toString());
    }

    private static int freePort() throws IOException {
        try (ServerSocket socket = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"))) {
            return socket.getLocalPort();
        }
    }

    private static void deleteFolder(Path root) {
        try (Stream<Path> files = Files.walk(root)) {
            for (Path file : files.sorted(Comparator.reverseOrder()).toList()) {
                Files.delete(file);
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
