package masl.jade.platform;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import jade.lang.acl.ACLMessage;
import masl.jade.JoiningContainerMain;
import masl.jade.Probe;
import masl.testing.jade.JadePlatformExtension;
import masl.testing.jade.SecondJvm;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;

/** A container in a second JVM joins this JVM's platform over loopback, and leaves no thread there. */
@Timeout(120)
@Tag("slow")
public class TwoJvmTest {

    @RegisterExtension
    static final JadePlatformExtension JADE = new JadePlatformExtension();

    @Test
    void aContainerInAnotherJvmJoinsExchangesAndItsJvmEndsByItself() throws Exception {
        JadePlatform main = JADE.platform();
        Probe probe = new Probe();
        main.container().acceptNewAgent("probe-main", probe).start();
        try (SecondJvm joined = SecondJvm.start(JoiningContainerMain.class, main.host(),
                Integer.toString(main.port()))) {
            ACLMessage hello = probe.next();
            assertEquals("hello from another JVM", hello.getContent());
            assertEquals("remote-greeter", hello.getSender().getLocalName());
            ACLMessage answer = hello.createReply();
            answer.setContent("welcome");
            probe.sendMessage(answer);
            String output = joined.assertEndsByItself();
            assertTrue(output.contains("answered: welcome"), output);
        }
    }
}
