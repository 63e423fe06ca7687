package masl.jade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jade.lang.acl.ACLMessage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import masl.jade.testing.JadePlatformExtension;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;

/** A container in a second JVM joins this JVM's platform over loopback, and leaves no thread there. */
@Timeout(120)
class TwoJvmTest {

    @RegisterExtension
    static final JadePlatformExtension JADE = new JadePlatformExtension();

    @Test
    void aContainerInAnotherJvmJoinsExchangesAndItsJvmEndsByItself() throws Exception {
        Path output = Files.createTempFile("masl-jade-joined-", ".log");
        try {
            JadePlatform main = JADE.platform();
            Probe probe = new Probe();
            main.container().acceptNewAgent("probe-main", probe).start();
            Process joined = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                    "-cp", System.getProperty("java.class.path"), JoiningContainerMain.class.getName(),
                    main.host(), Integer.toString(main.port()))
                    .redirectErrorStream(true)
                    .redirectOutput(output.toFile())
                    .start();
            try {
                ACLMessage hello = probe.next();
                assertEquals("hello from another JVM", hello.getContent());
                assertEquals("remote-greeter", hello.getSender().getLocalName());
                ACLMessage answer = hello.createReply();
                answer.setContent("welcome");
                probe.sendMessage(answer);
                assertTrue(joined.waitFor(60, TimeUnit.SECONDS),
                        "the joined JVM did not end by itself:\n" + Files.readString(output));
                assertEquals(0, joined.exitValue(), Files.readString(output));
                assertTrue(Files.readString(output).contains("answered: welcome"), Files.readString(output));
            } finally {
                joined.destroyForcibly();
            }
        } finally {
            Files.deleteIfExists(output);
        }
    }
}
