package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.net.Inet4Address;
import java.net.InetAddress;
import java.net.NetworkInterface;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collections;
import java.util.List;
import masl.cli.Main;
import masl.testing.jade.SecondJvm;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A mission deployed over a network address rather than loopback, as on robots: {@code masl run
 * --local-host A --port P --deploy '*=c2'} starts its main container on address A, and {@code masl
 * container --main-host A --local-host A} joins it from a second JVM, listening on A too. A is this
 * machine's first address on a network: the JVMs bind the address asked, and each reaches the other
 * there. A machine on no network has no such address, and skips this test.
 */
@Timeout(120)
@Tag("slow")
class LocalHostDeploymentTest {

    @Test
    void e2DeployedOverANetworkAddressWritesItsJournal() throws Exception {
        String address = networkAddress();
        assumeTrue(address != null, "this machine has no address on a network");
        int port = freePort(address);
        Path secretFile = Files.createTempDirectory("masl-mission").resolve("secret");
        try (SecondJvm container = SecondJvm.start(Main.class, "container", "--main-host", address,
                "--main-port", String.valueOf(port), "--local-host", address, "--name", "c2", "--timeout", "60",
                "--secret-file", secretFile.toString())) {
            MaslCommand run = MaslCommand.run("run", "src/test/resources/examples/e2_shared_and_local.masl",
                    "--platform", "jade", "--local-host", address, "--port", String.valueOf(port), "--deploy", "*=c2",
                    "--timeout", "60", "--secret-file", secretFile.toString());

            assertEquals("masl: platform ready: host=" + address + " port=" + port + " platform=" + address + ":" + port
                    + "/JADE\n", run.err(), container.output());
            assertEquals(0, run.status(), container.output());
            assertEquals("n=5\n" + "mine=1\n".repeat(5), run.out());
            List<String> hosted = container.assertEndsByItself().lines().toList();
            assertTrue(hosted.contains("masl-ended hosted a,b,c,d,e"), hosted.toString());
        } finally {
            Files.deleteIfExists(secretFile);
            Files.delete(secretFile.getParent());
        }
    }

    /** The first IPv4 address of an interface that is up and not loopback, or null. */
    private static String networkAddress() throws IOException {
        for (NetworkInterface nic : Collections.list(NetworkInterface.getNetworkInterfaces())) {
            if (nic.isUp() && !nic.isLoopback()) {
                for (InetAddress address : Collections.list(nic.getInetAddresses())) {
                    if (address instanceof Inet4Address && !address.isLinkLocalAddress()) {
                        return address.getHostAddress();
                    }
                }
            }
        }
        return null;
    }

    private static int freePort(String address) throws IOException {
        try (ServerSocket socket = new ServerSocket(0, 1, InetAddress.getByName(address))) {
            return socket.getLocalPort();
        }
    }
}
