package masl.maven;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The source root of the generated Java: nothing stale, nothing rewritten for nothing, nothing of the user's touched. */
class GeneratedSourcesTest {

    private static final FileTime LONG_AGO = FileTime.fromMillis(1_000_000_000_000L);

    @TempDir
    Path root;

    @Test
    void aProgramNoLongerTranslatedLeavesNoSourceBehindAndNothingElseIsTouched() throws Exception {
        Path mine = Files.writeString(Files.createDirectories(root.resolve("sample")).resolve("Mine.java"), "class Mine {}");
        GeneratedSources sources = new GeneratedSources(root);
        sources.update(Map.of("masl.generated.count.CountMission", "class CountMission {}",
                "masl.generated.tally.TallyMission", "class TallyMission {}"));

        sources.update(Map.of("masl.generated.count.CountMission", "class CountMission {}"));

        assertTrue(Files.isRegularFile(root.resolve("masl/generated/count/CountMission.java")));
        assertFalse(Files.exists(root.resolve("masl/generated/tally")), "the folder of a program no longer translated");
        assertEquals("class Mine {}", Files.readString(mine));
    }

    @Test
    void anUnchangedSourceIsNotWrittenAgainAndAChangedOneIs() throws Exception {
        GeneratedSources sources = new GeneratedSources(root);
        sources.update(Map.of("masl.generated.count.CountMission", "class CountMission {}",
                "masl.generated.count.Agents", "class Agents {}"));
        Path unchanged = root.resolve("masl/generated/count/CountMission.java");
        Path changed = root.resolve("masl/generated/count/Agents.java");
        Files.setLastModifiedTime(unchanged, LONG_AGO);
        Files.setLastModifiedTime(changed, LONG_AGO);

        sources.update(Map.of("masl.generated.count.CountMission", "class CountMission {}",
                "masl.generated.count.Agents", "class Agents { int n; }"));

        assertEquals(LONG_AGO, Files.getLastModifiedTime(unchanged));
        assertEquals("class Agents { int n; }", Files.readString(changed));
        assertTrue(Files.getLastModifiedTime(changed).compareTo(LONG_AGO) > 0);
    }
}
