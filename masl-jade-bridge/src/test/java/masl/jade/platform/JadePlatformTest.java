package masl.jade.platform;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jade.core.AID;
import jade.lang.acl.ACLMessage;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.URI;
import java.nio.file.Files;
import java.util.List;
import java.util.Optional;
import masl.jade.Probe;
import masl.testing.jade.ThreadSnapshot;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** Starting, joining and shutting down JADE containers: loopback only, no thread left behind. */
@Timeout(120)
class JadePlatformTest {

    @Test
    void mainContainerListensOnLoopbackAndLeavesNoThreadBehind() throws Exception {
        ThreadSnapshot before = ThreadSnapshot.take();
        JadePlatform platform = JadePlatform.start(JadeOptions.mainContainer());
        try {
            assertTrue(platform.isMain());
            assertEquals("127.0.0.1", platform.host());
            try (Socket socket = new Socket()) {
                socket.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), platform.port()), 5000);
            }
            assertFalse(JadeThreads.live().isEmpty(), "a running platform has JADE threads");
            assertTrue(Files.exists(platform.fileDir().resolve("APDescription.txt")),
                    "JADE's files go to the platform's own folder");
        } finally {
            platform.close();
        }
        assertEquals(List.of(), before.startedSince());
        assertFalse(Files.exists(platform.fileDir()), "the platform's folder is deleted");
        platform.close(); // idempotent
    }

    @Test
    void aJoinedContainerReachesAgentsOfTheMainContainer() throws Exception {
        ThreadSnapshot before = ThreadSnapshot.take();
        try (JadePlatform main = JadePlatform.start(JadeOptions.mainContainer());
                JadePlatform joined = JadePlatform.start(JadeOptions.join(main.host(), main.port()))) {
            assertFalse(joined.isMain());
            assertEquals(main.platformName(), joined.platformName());
            assertNotEquals(main.containerName(), joined.containerName());
            Probe inMain = new Probe();
            Probe inJoined = new Probe();
            main.container().acceptNewAgent("probe-main", inMain).start();
            joined.container().acceptNewAgent("probe-joined", inJoined).start();
            ACLMessage hello = new ACLMessage(ACLMessage.INFORM);
            hello.addReceiver(new AID("probe-main", AID.ISLOCALNAME));
            hello.setContent("hello");
            inJoined.sendMessage(hello);
            ACLMessage received = inMain.next();
            assertEquals("hello", received.getContent());
            assertEquals("probe-joined", received.getSender().getLocalName());
        }
        assertEquals(List.of(), before.startedSince());
    }

    @Test
    void theHttpTransportStartsOnlyWhenAskedAndOnLoopback() throws Exception {
        ThreadSnapshot before = ThreadSnapshot.take();
        try (JadePlatform platform = JadePlatform.start(JadeOptions.mainContainer().withHttpTransport(true))) {
            URI address = URI.create(platform.httpAddress().orElseThrow());
            assertEquals("127.0.0.1", address.getHost());
            try (Socket socket = new Socket()) {
                socket.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), address.getPort()), 5000);
            }
        }
        assertEquals(List.of(), before.startedSince());
        try (JadePlatform platform = JadePlatform.start(JadeOptions.mainContainer())) {
            assertEquals(Optional.empty(), platform.httpAddress());
        }
    }

    @Test
    void aTakenPortIsReportedNotRetried() throws IOException {
        try (ServerSocket taken = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            JadeException failure = assertThrows(JadeException.class,
                    () -> JadePlatform.start(JadeOptions.mainContainer().withPort(taken.getLocalPort())));
            assertEquals("cannot start a JADE main container on 127.0.0.1:" + taken.getLocalPort()
                    + " (is the port free?)", failure.getMessage());
        }
    }

    @Test
    void joiningWhereNoPlatformRunsIsReported() throws IOException {
        int nobody;
        try (ServerSocket probe = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            nobody = probe.getLocalPort();
        }
        JadeException failure = assertThrows(JadeException.class,
                () -> JadePlatform.start(JadeOptions.join("127.0.0.1", nobody)));
        assertEquals("cannot join the JADE platform at 127.0.0.1:" + nobody + " (is its main container running?)",
                failure.getMessage());
    }
}
