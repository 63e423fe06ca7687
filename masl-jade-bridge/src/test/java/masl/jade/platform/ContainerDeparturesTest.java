package masl.jade.platform;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Optional;
import org.junit.jupiter.api.Test;

/** What JADE says of a container that left abruptly is one line of masl's, once per container. */
class ContainerDeparturesTest {

    @Test
    void jadesLinesOfADepartureAreOneLineOfMaslsOnce() {
        assertEquals(Optional.of(""), ContainerDepartures.inMaslWords("EOF reached"));
        assertEquals(Optional.of("masl: container lab-7 left the platform (its JVM ended or its connection broke)"),
                ContainerDepartures.inMaslWords("--- Node <lab-7> UNREACHABLE ---"));
        assertEquals(Optional.of(""), ContainerDepartures.inMaslWords(
                "jade.core.NotFoundException: No container named lab-7 was found."));
    }

    @Test
    void anAmsRemovingAContainerTwiceSaysItsDepartureIfNothingElseDid() {
        assertEquals(Optional.of("masl: container lab-8 left the platform (its JVM ended or its connection broke)"),
                ContainerDepartures.inMaslWords("jade.core.NotFoundException: No container named lab-8 was found"));
    }

    @Test
    void jadesOwnWordsEndWithAFullStop() {
        assertEquals(Optional.of("masl: container lab-9 left the platform (its JVM ended or its connection broke)"),
                ContainerDepartures.inMaslWords("jade.core.NotFoundException: No container named lab-9 was found."));
        assertEquals(Optional.of(""),
                ContainerDepartures.inMaslWords("jade.core.NotFoundException: No container named lab-9 was found."));
    }

    @Test
    void aShutdownThatCannotEndAContainerThatLeftSaysNothingMore() {
        ContainerDepartures.inMaslWords("--- Node <lab-10> UNREACHABLE ---");

        assertEquals(Optional.of(""), ContainerDepartures.inMaslWords("Cannot kill container lab-10: Unreachable."));
    }

    @Test
    void aShutdownThatCannotEndAContainerNotKnownToHaveLeftIsSaidAsJadeSaysIt() {
        assertEquals(Optional.empty(), ContainerDepartures.inMaslWords("Cannot kill container Main-Container: Unreachable."));
    }

    @Test
    void otherLinesAreNotADeparture() {
        assertEquals(Optional.empty(), ContainerDepartures.inMaslWords("Receiver unreachable."));
        assertEquals(Optional.empty(), ContainerDepartures.inMaslWords("jade.core.NotFoundException: No agent named x"));
    }
}
