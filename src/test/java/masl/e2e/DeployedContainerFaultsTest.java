package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import masl.cli.Main;
import masl.testing.jade.SecondJvm;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * A deployed mission loses a JVM: {@code away}'s program runs in container {@code c2} (a JVM of its
 * own), {@code stay}'s in the coordinator's. Container killed while {@code away} is parked in a
 * sleep and {@code stay} waits for it at their block's barrier: {@code away} fails, naming the
 * container, the barrier stops waiting for it, {@code stay} goes on to the end of its journal, the
 * mission ends with status 2 long before its timeout and its trace is complete. Coordinator killed:
 * the container stops its agent, says why in one line and exits 2.
 */
@Timeout(180)
@Tag("slow")
class DeployedContainerFaultsTest {

    private static final String PROGRAM = """
            import Default.xml as Default;
            Default stay, away = newAgent(Default);
            asynchronous entry main (true) {
              shared int ready = 0;
              asynchronous entry roam (.getProxyID() == 1) {
                ready = 1;
                while (true) { .sleep(20); }
              }
              asynchronous entry hold (.getProxyID() == 0) {
                while (ready == 0) {}
                .logln("stay done");
              }
            }
            """;

    /** {@code away} sleeps through step 5 of a lock-step in which {@code stay} says it waits. */
    private static final String LOCK_STEP = """
            import Default.xml as Default;
            Default stay, away = newAgent(Default);
            synchronous entry main (true) {
              local int i = 0;
              while (i < 10) {
                i++;
                if (i == 5) {
                  if (.getProxyID() == 1) { .sleep(600000); } else { .logln("stay waits"); }
                }
              }
              if (.getProxyID() == 0) { .logln("stay done after " + i); }
            }
            """;

    @TempDir
    Path folder;

    @Test
    void aKilledContainerFailsItsAgentsAndTheOthersGoOn() throws Exception {
        int port = freePort();
        Path program = Files.writeString(folder.resolve("faults.masl"), LOCK_STEP);
        File journal = folder.resolve("journal.txt").toFile();
        Path trace = folder.resolve("trace.jsonl");
        Path secret = folder.resolve("secret");
        try (SecondJvm c2 = container(port, secret);
                MaslProcess run = MaslProcess.start(journal, "run", program.toString(), "--platform", "jade", "--port",
                        String.valueOf(port), "--deploy", "away=c2", "--timeout", "120", "--secret-file", secret.toString(),
                        "--trace", trace.toString(), "--quiet")) {
            awaitJournal(journal, "stay waits\n");
            c2.kill();
            assertEquals(2, run.awaitExit(), run.err());
            assertEquals("stay waits\nstay done after 10\n", Files.readString(journal.toPath()));
            assertTrue(run.err().lines().anyMatch(line -> line.equals("masl: the container c2 is gone (its JVM ended or"
                    + " died): its deployed agents away fail") || line.equals("masl: the deployed agents away, whose"
                    + " container c2 left, fail")), run.err());
            String failed = Files.readString(trace).lines().filter(line -> line.contains("\"event\":\"agent-failed\""))
                    .findFirst().orElse("");
            assertTrue(failed.contains("\"agent\":1") && failed.contains("the container c2 is gone"), failed);
            assertTrue(Files.readString(trace).lines().reduce((first, last) -> last).orElse("")
                    .contains("\"event\":\"mission-ended\""), "a complete trace");
        }
    }

    @Test
    void aContainerWhoseCoordinatorIsKilledStopsItsAgentsAndSaysWhy() throws Exception {
        int port = freePort();
        Path program = Files.writeString(folder.resolve("faults.masl"), PROGRAM);
        File journal = folder.resolve("journal.txt").toFile();
        Path secret = folder.resolve("secret");
        try (SecondJvm c2 = container(port, secret);
                MaslProcess run = MaslProcess.start(journal, "run", program.toString(), "--platform", "jade", "--port",
                        String.valueOf(port), "--deploy", "away=c2", "--timeout", "120", "--secret-file", secret.toString(),
                        "--quiet")) {
            awaitJournal(journal, "stay done\n");
            run.process().destroyForcibly();
            assertEquals(2, c2.awaitExit(), c2.output());
            assertTrue(c2.output().lines().anyMatch(line -> line.startsWith("masl: container c2: the mission's coordinator"
                    + " is gone") && line.endsWith("; its agents were stopped")), c2.output());
        }
    }

    /** Waits, up to two minutes, until the journal file holds {@code text}. */
    private static void awaitJournal(File journal, String text) throws Exception {
        for (int tries = 0; tries < 1200; tries++) {
            if (journal.exists() && Files.readString(journal.toPath()).equals(text)) {
                return;
            }
            Thread.sleep(100);
        }
        throw new AssertionError("the journal never held " + text + ": " + Files.readString(journal.toPath()));
    }

    private static SecondJvm container(int port, Path secretFile) throws IOException {
        return SecondJvm.start(Main.class, "container", "--main-host", "127.0.0.1", "--main-port", String.valueOf(port),
                "--name", "c2", "--timeout", "120", "--secret-file", secretFile.toString());
    }

    private static int freePort() throws IOException {
        try (ServerSocket socket = new ServerSocket(0, 1, InetAddress.getByName("127.0.0.1"))) {
            return socket.getLocalPort();
        }
    }
}
