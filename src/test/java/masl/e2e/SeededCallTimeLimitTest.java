package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Set;
import java.util.function.Consumer;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code masl run --seed N --call-timeout MS} names one run: primitives' sleeps through their
 * agent's services and the call time limit count in the seeded run's own (mission) time, so the
 * machine's speed decides nothing (agent type {@code agents/Sleeper.xml}).
 */
@Timeout(300)
class SeededCallTimeLimitTest {

    /** The test's own classes hold the implementation of {@code agents/Sleeper.xml}. */
    private static final String TEST_CLASSES = "build/classes/java/test";

    /**
     * Each line comes at its moment of mission time (in ms): the futures' dozes (50, 60, 70), agent
     * 0's labelled doze (90), the wake-ups (120, 130, 140), agent 1's labelled doze (190) seen by its
     * polling loop (193), agent 2's labelled doze given up at the limit (200, seen at 203), then
     * agent 0's naps, held by its call: within the limit, then given up at it.
     */
    private static final String MISSION_TIME_ORDER = """
            0 dozed 50
            1 dozed 60
            2 dozed 70
            0 dozed 90
            0 woke y=50
            0 x=90
            1 woke y=60
            2 woke y=70
            1 dozed 190
            1 x=190
            2 timeout doze
            2 x=0
            0 napped 50
            0 nap 50
            0 timeout nap
            0 nap 0
            """;

    @TempDir
    Path folder;

    @Test
    void sleepsAndCallTimeLimitsWithLabelsAndFuturesFollowMissionTimeUnderEverySeed() {
        for (long seed = 0; seed < 6; seed++) {
            for (int run = 0; run < 2; run++) {
                MaslCommand masl = MaslCommand.run("run", "src/test/resources/faults/sleeping_primitives.masl",
                        "--agent-path", TEST_CLASSES, "--call-timeout", "200", "--seed", Long.toString(seed));
                assertEquals(0, masl.status(), masl::toString);
                assertEquals(MISSION_TIME_ORDER, masl.out(), "seed " + seed + ", run " + run);
            }
        }
    }

    /** Given up when mission time reaches the limit (100): after agent 0's sleep (50), before agent 1's (150). */
    @Test
    void aPrimitiveWaitingForWhatNeverComesIsGivenUpAtTheLimitInMissionTime() {
        for (long seed = 0; seed < 6; seed++) {
            MaslCommand masl = MaslCommand.run("run", "src/test/resources/faults/stalling_primitive.masl",
                    "--agent-path", TEST_CLASSES, "--call-timeout", "100", "--seed", Long.toString(seed));
            assertEquals(0, masl.status(), masl::toString);
            assertEquals("0 slept, finished=false\n0 timeout stall\n0 r=0\n"
                    + "1 timeout stall\n1 slept, finished=true\n1 r=0\n", masl.out(), "seed " + seed);
        }
    }

    /**
     * One JVM per run, so that nothing one run left warm (loaded classes, threads) helps the next:
     * the primitive sleeping past the limit in a synchronous block, and the labels and futures.
     */
    @Test
    @Tag("slow")
    void eachSeedGivesOneJournalAcrossProcesses() throws Exception {
        assertOneJournalPerSeed("sleep_past_call_timeout.masl", "100", journal -> assertTrue(
                journal.contains("0 timeout\n") && journal.contains("0 x=0\n")
                        && journal.contains("1 timeout\n") && journal.contains("1 x=0\n"), journal));
        assertOneJournalPerSeed("sleeping_primitives.masl", "200", journal -> assertEquals(MISSION_TIME_ORDER, journal));
    }

    private void assertOneJournalPerSeed(String program, String callTimeout, Consumer<String> expected) throws Exception {
        Map<Long, Set<String>> journals = new LinkedHashMap<>();
        for (long seed = 1; seed <= 3; seed++) {
            for (int run = 0; run < 3; run++) {
                File out = folder.resolve(program + "-" + seed + "-" + run + ".txt").toFile();
                try (MaslProcess masl = MaslProcess.start(out, "run", "src/test/resources/faults/" + program,
                        "--agent-path", TEST_CLASSES, "--call-timeout", callTimeout, "--seed", Long.toString(seed), "--quiet")) {
                    assertEquals(0, masl.awaitExit(), masl::toString);
                }
                journals.computeIfAbsent(seed, any -> new LinkedHashSet<>()).add(Files.readString(out.toPath()));
            }
        }
        journals.forEach((seed, seen) -> {
            assertEquals(1, seen.size(), program + ": seed " + seed + " gave " + seen);
            expected.accept(seen.iterator().next());
        });
    }
}
