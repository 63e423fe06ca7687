package masl.jade.placement;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code --place}: pairs on the command line or in a file; mistakes with their positions. */
class PlacementTest {

    @TempDir
    Path folder;

    @Test
    void pairsOnTheCommandLineKeepTheirOrder() {
        assertEquals(List.of("w1", "w3"), List.copyOf(Placement.parse("w1=c2, w3 = c-3").keySet()));
        assertEquals(Map.of("w1", "c2", "w3", "c-3"), Placement.parse("w1=c2, w3 = c-3"));
    }

    @Test
    void aFileHoldsOnePairPerLineWithComments() throws Exception {
        Path file = Files.writeString(folder.resolve("places.txt"), "# robots in the lab\nw1=lab\n\nw2 = lab # near\n");
        assertEquals(Map.of("w1", "lab", "w2", "lab"), Placement.parse(file.toString()));
    }

    @Test
    void mistakesArePositioned() throws Exception {
        assertEquals("--place w1=c2,w2: column 7: error: expected AGENT=CONTAINER, got 'w2'", message("w1=c2,w2"));
        assertEquals("--place w1=c2,w2=c 2: column 10: error: 'c 2' is not a container name (letters, digits, '_', '.', '-')",
                message("w1=c2,w2=c 2"));
        assertEquals("--place w1=c2,w1=c3: column 7: error: w1 is placed twice", message("w1=c2,w1=c3"));
        assertEquals("--place 1w=c2: column 1: error: '1w' is not an agent name", message("1w=c2"));
        Path file = Files.writeString(folder.resolve("places.txt"), "w1=lab\n  w2 lab\n");
        assertEquals(file + ":2:3: error: expected AGENT=CONTAINER, got 'w2 lab'", message(file.toString()));
        assertEquals("cannot read placement file " + folder.resolve("none"),
                message(folder.resolve("none").toString()).replaceAll(": [^:]*$", ""));
    }

    private static String message(String option) {
        return assertThrows(IllegalArgumentException.class, () -> Placement.parse(option)).getMessage();
    }
}
