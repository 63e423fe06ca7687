package masl.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import masl.cli.CheckCommandTest.Run;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** {@code masl run --platform jade}: the same journal, statuses and errors as in-process. */
@Timeout(120)
class JadeRunTest {

    private static final String HEADER = "import Default.xml as Default;\nDefault a, b = newAgent(Default);\n";

    @TempDir
    Path folder;

    private String write(String name, String text) throws IOException {
        Path file = folder.resolve(name);
        Files.writeString(file, text);
        return file.toString();
    }

    @Test
    void aMissionInsideJadeWritesTheJournalAndSaysOnceWhereThePlatformAcceptsContainers() throws IOException {
        String program = write("two.masl", HEADER + """
                synchronous entry main (true) {
                  .log("x");
                  scalar entry end (true) { .logln(""); }
                }
                """);
        Run run = Run.of("run", program, "--platform", "jade");
        assertEquals(0, run.status(), run::toString);
        assertEquals("xx\n", run.out());
        assertTrue(run.err().matches("masl: platform ready: host=127\\.0\\.0\\.1 port=(\\d+) platform=127\\.0\\.0\\.1:\\1/JADE\n"),
                run.err());
    }

    /** In-process this busy-wait is a deadlock; inside JADE a FIPA request might end it, so it waits. */
    @Test
    void aBusyWaitInsideJadeWaitsForRequestsUntilTheTimeout() throws IOException {
        Run run = Run.of("run", write("waiting.masl", HEADER + """
                asynchronous entry main (true) {
                  shared int go = 0;
                  while (go == 0) {}
                }
                """), "--platform=jade", "--timeout", "1");
        assertEquals(2, run.status());
        assertEquals("", run.out());
        assertTrue(run.err().lines().skip(1).findFirst().orElse("").startsWith("masl: the mission timed out"),
                run.err());
    }

    @Test
    void aMainContainerThatIsNotThereFailsTheMission() throws IOException {
        int freePort;
        try (ServerSocket probe = new ServerSocket(0)) {
            freePort = probe.getLocalPort();
        }
        Run run = Run.of("run", write("one.masl", HEADER + "scalar entry main (true) { .nop(); }\n"),
                "--platform", "jade", "--main-host", "127.0.0.1", "--main-port", String.valueOf(freePort));
        assertEquals(2, run.status());
        assertEquals("", run.out());
        assertEquals("masl: cannot join the JADE platform at 127.0.0.1:" + freePort + " (is its main container running?)\n",
                run.err());
    }

    @Test
    void optionsThatDoNotFitThePlatformAreBadUsage() throws IOException {
        String program = write("one.masl", HEADER + "scalar entry main (true) { .nop(); }\n");
        assertEquals(64, Run.of("run", program, "--platform", "corba").status());
        assertEquals(64, Run.of("run", program, "--platform", "jade", "--seed", "1").status());
        assertEquals(64, Run.of("run", program, "--platform", "jade", "--threads").status());
        assertEquals(64, Run.of("run", program, "--platform", "jade", "--main-host", "127.0.0.1").status());
        assertEquals(64, Run.of("run", program, "--platform", "jade", "--main-host", "h", "--main-port", "70000")
                .status());
        assertEquals(64, Run.of("run", program, "--main-host", "127.0.0.1", "--main-port", "1099").status());
    }

    @Test
    void aPlacementThatDoesNotFitTheProgramIsBadUsageWithItsPosition() throws IOException {
        String program = write("one.masl", HEADER + "scalar entry main (true) { .nop(); }\n");
        Run undeclared = Run.of("run", program, "--platform", "jade", "--place", "a=c2,zed=c2");
        assertEquals(64, undeclared.status());
        assertTrue(undeclared.err().startsWith("masl: --place names zed, which the program does not declare (it"
                + " declares a, b)\n"), undeclared.err());
        Run malformed = Run.of("run", program, "--platform", "jade", "--place", "a=c2,b");
        assertEquals(64, malformed.status());
        assertTrue(malformed.err().startsWith("masl: --place a=c2,b: column 6: error: expected AGENT=CONTAINER, got 'b'\n"),
                malformed.err());
        assertEquals(64, Run.of("run", program, "--place", "a=c2").status(), "--place needs --platform jade");
        assertEquals(64, Run.of("run", program, "--platform", "jade", "--port", "1099", "--main-host", "h",
                "--main-port", "1099").status(), "--port starts a main container, --main-* join one");
        Run secretAlone = Run.of("run", program, "--platform", "jade", "--secret-file", "s");
        assertEquals(64, secretAlone.status());
        assertTrue(secretAlone.err().startsWith("masl: --secret-file is where the containers of --place and --deploy"
                + " find the mission's secret: give it with --place or --deploy\n"), secretAlone.err());
        assertEquals(64, Run.of("run", program, "--secret-file", "s").status(), "--secret-file needs --platform jade");
    }

    @Test
    void aDeploymentThatDoesNotFitTheProgramIsBadUsageWithItsPosition() throws IOException {
        String program = write("two.masl", HEADER + "scalar entry main (true) { .nop(); }\n");
        Run undeclared = Run.of("run", program, "--platform", "jade", "--deploy", "a=c2,zed=c3");
        assertEquals(64, undeclared.status());
        assertTrue(undeclared.err().startsWith("masl: --deploy:1:6: error: zed is not an agent of the program (it"
                + " declares a, b)\n"), undeclared.err());
        Run both = Run.of("run", program, "--platform", "jade", "--place", "a=c2", "--deploy", "*=c3,a=c3");
        assertEquals(64, both.status());
        assertTrue(both.err().startsWith("masl: --deploy:1:6: error: a is placed with --place"), both.err());
        assertEquals(64, Run.of("run", program, "--deploy", "*=c2").status(), "--deploy needs --platform jade");
    }

    /** A file named as the secret's is the user's: the mission does not start, and the file is as it was. */
    @Test
    void aSecretFileThatExistsIsRefusedAndKept() throws IOException {
        String program = write("one.masl", HEADER + "scalar entry main (true) { .nop(); }\n");
        String notes = write("notes.txt", "my notes\n");
        Run run = Run.of("run", program, "--platform", "jade", "--place", "b=c2", "--secret-file", notes);
        assertEquals(2, run.status(), run::toString);
        assertTrue(run.err().contains("masl: cannot write the mission's secret for its containers to " + notes
                + ": it exists, and the mission's secret is written only to a file the mission creates"), run.err());
        assertEquals("my notes\n", Files.readString(Path.of(notes)));
    }

    /** 203.0.113.1 is of TEST-NET-3, never a machine's own address. */
    @Test
    void aLocalHostIsAnAddressOfThisMachineAndJoiningAnotherMachineNeedsOne() throws IOException {
        String program = write("one.masl", HEADER + "scalar entry main (true) { .nop(); }\n");
        Run elsewhere = Run.of("run", program, "--platform", "jade", "--local-host", "203.0.113.1");
        assertEquals(64, elsewhere.status());
        assertTrue(elsewhere.err().startsWith("masl: --local-host 203.0.113.1 is not an address of this machine: give the"
                + " one the other machines reach it at\n"), elsewhere.err());
        Run everywhere = Run.of("container", "--main-host", "127.0.0.1", "--main-port", "1099", "--name", "c2",
                "--local-host", "0.0.0.0");
        assertEquals(64, everywhere.status());
        assertTrue(everywhere.err().startsWith("masl: --local-host 0.0.0.0 is every address of this machine"), everywhere.err());
        Run unbound = Run.of("run", program, "--platform", "jade", "--local-host", "127.0.0.2");
        assertEquals(64, unbound.status());
        assertTrue(unbound.err().startsWith("masl: --local-host 127.0.0.2 is no interface's address, which JADE binds to"),
                unbound.err());
        Run withoutJade = Run.of("run", program, "--local-host", "127.0.0.1");
        assertEquals(64, withoutJade.status());
        assertTrue(withoutJade.err().startsWith("masl: --place, --deploy, --port, --local-host and --secret-file are for a"
                + " JADE platform: give them with --platform jade\n"), withoutJade.err());

        String onLoopback = "masl: the main container at 203.0.113.1 is on another machine, which cannot reach this JVM's"
                + " container on loopback: give --local-host ADDRESS, this machine's address on their network\n";
        Run container = Run.of("container", "--main-host", "203.0.113.1", "--main-port", "1099", "--name", "c2");
        assertEquals(64, container.status());
        assertTrue(container.err().startsWith(onLoopback), container.err());
        Run joining = Run.of("run", program, "--platform", "jade", "--main-host", "203.0.113.1", "--main-port", "1099");
        assertEquals(64, joining.status());
        assertTrue(joining.err().startsWith(onLoopback), joining.err());
    }

    @Test
    void aContainerNeedsItsPlatformAndName() {
        Run noName = Run.of("container", "--main-host", "127.0.0.1", "--main-port", "1099");
        assertEquals(64, noName.status());
        assertTrue(noName.err().startsWith("masl: masl container needs --main-host, --main-port and --name\n"),
                noName.err());
        assertEquals(64, Run.of("container", "--main-host", "h", "--main-port", "1", "--name", "c", "x.masl").status());
    }
}
