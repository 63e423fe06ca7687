package masl.jade.platform;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

class ReadinessTest {

    @Test
    void aPlatformLineGivesWhereToJoin() {
        assertEquals(Optional.of(new Readiness(Optional.empty(), "127.0.0.1", 41234, "127.0.0.1:41234/JADE", List.of())),
                Readiness.parse("masl: platform ready: host=127.0.0.1 port=41234 platform=127.0.0.1:41234/JADE"));
    }

    @Test
    void aContainerLineGivesItsNameAndItsAgentsInOrder() {
        assertEquals(Optional.of(new Readiness(Optional.of("c2"), "127.0.0.1", 1099, "p", List.of("w3", "b"))),
                Readiness.parse("masl: container ready: name=c2 host=127.0.0.1 port=1099 platform=p agents=w3,b"));
    }

    @Test
    void otherLinesAreNoReadiness() {
        for (String line : List.of("", "masl: the mission failed", "masl: platform ready: host=h port=99999999 platform=p",
                "masl: platform ready: host=h port=1 platform=p agents=a",
                "masl: container ready: name=c host=h port=1 platform=p",
                "  masl: platform ready: host=h port=1 platform=p")) {
            assertEquals(Optional.empty(), Readiness.parse(line), line);
        }
    }
}
