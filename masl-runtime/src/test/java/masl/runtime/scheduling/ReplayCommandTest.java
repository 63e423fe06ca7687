package masl.runtime.scheduling;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The replay hint in the words of each tool, as a shell takes it. */
class ReplayCommandTest {

    @Test
    void theMaslCommandWithTheOptionsOfTheRun() {
        assertEquals("masl run missions/e2.masl --agent-path robots:lib/arm.jar --seed 7",
                ReplayCommand.masl("missions/e2.masl", List.of("--agent-path", "robots:lib/arm.jar")).forSeed(7));
    }

    @Test
    void aWordWithSpacesOrQuotesIsQuotedForTheShell() {
        assertEquals("masl run 'my missions/it'\\''s.masl' --seed -3",
                ReplayCommand.masl("my missions/it's.masl", List.of()).forSeed(-3));
    }

    @Test
    void theBuildsTasksWithTheirProperties() {
        assertEquals("gradle maslRun -Pmission=hello -PcallTimeout=500 -Pseed=12",
                ReplayCommand.gradle("hello", List.of("callTimeout=500")).forSeed(12));
        assertEquals("mvn masl:run -Dmission=hello -Dseed=12", ReplayCommand.maven("hello", List.of()).forSeed(12));
    }

    @Test
    void aTemplateTravelsAsItsTextAndNeedsTheSeedsPlace() {
        ReplayCommand gradle = ReplayCommand.gradle("hello", List.of());
        assertEquals("gradle maslRun -Pmission=hello -Pseed=5", ReplayCommand.of(gradle.template()).forSeed(5));
        IllegalArgumentException noSeed = assertThrows(IllegalArgumentException.class, () -> ReplayCommand.of("gradle maslRun"));
        assertEquals("a replay command takes the seed where it says {seed}: gradle maslRun", noSeed.getMessage());
    }
}
