package masl.e2e;

import java.time.Duration;
import java.util.List;
import masl.testing.MaslMission;
import masl.testing.MissionPlatform;
import masl.testing.jade.DeployedInMemory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Arrays held by shared variables, with the programs deployed: every element type MASL has travels
 * between the mission and the containers, and each store into an element, plain, compound or an
 * increment, is made in the mission's array, which every agent then reads, as in-process. Each agent
 * writes its own elements, so that the journal does not depend on the order of the agents' steps.
 */
@Timeout(120)
class DeployedSharedArraysTest {

    private static final Duration TIMEOUT = Duration.ofSeconds(30);

    private static final String TEAM = """
            import Default.xml as Default;
            Default a, b, c = newAgent(Default);
            synchronous entry main (true) {
              shared String[] names = new String[main.count];
              shared Default[] team = new Default[main.count];
              shared int[][] grid = new int[2][3];
              shared long[] big = new long[3];
              shared double[] halves = new double[3];
              shared char[] letters = new char[3];
              shared boolean[] seen = new boolean[3];
              local int me = .getProxyID();
              names[.getProxyID()] = "agent " + me;
              names[me] = names[me] + "!";
              team[me] = this;
              grid[1][.getProxyID()] += 2 + me;
              grid[0][me]++;
              big[me] = 10000000000L * me;
              halves[me] = me / 2.0;
              halves[me] *= 3;
              letters[me] = (char) ('a' + me);
              ++letters[me];
              seen[me] = true;
              scalar entry report (true) {
                local int before = grid[0][0]++;
                local int set = (grid[1][0] = 7);
                .logln(String.join(",", names) + " " + grid[0][0] + grid[0][1] + grid[0][2] + " " + grid[1][0]
                    + grid[1][1] + grid[1][2] + " " + before + set + " " + big[2] + " " + halves[1] + " "
                    + new String(letters) + seen[2] + " " + (team[0] == a && team[1] == b && team[2] == c)
                    + " " + grid.length + names.length);
              }
            }
            """;

    private static final String JOURNAL = "agent 0!,agent 1!,agent 2! 211 734 17 20000000000 1.5 bcdtrue true 23\n";

    @Test
    void everyElementTypeAndEveryStoreGiveTheJournalTheyGiveInProcess() {
        MaslMission mission = MaslMission.fromString("team.masl", TEAM).timeout(TIMEOUT);
        mission.run().assertJournal(JOURNAL);
        for (MissionPlatform deployment : List.<MissionPlatform>of(DeployedInMemory.everyAgent(),
                DeployedInMemory.spread(), DeployedInMemory.agents("b"))) {
            mission.runOn(deployment).assertJournal(JOURNAL);
        }
    }

    /**
     * A busy-wait loop on an element (MASL §5) wakes when an agent in a container stores it: {@code a}
     * runs in the mission's JVM and waits for {@code b}'s store, which the mission makes for it, while
     * {@code b} waits for {@code a}'s next store, so that nothing else wakes {@code a}.
     */
    @Test
    void aBusyWaitLoopWakesWhenAnAgentElsewhereStoresTheElementItWaitsFor() {
        MaslMission mission = MaslMission.fromString("handshake.masl", """
                import Default.xml as Default;
                Default a, b = newAgent(Default);
                asynchronous entry main (true) {
                  shared int[] flags = new int[2];
                  if (.getProxyID() == 0) {
                    flags[0] = 1;
                    while (flags[1] != 1) { }
                    .logln("a saw b");
                    flags[0] = 2;
                  } else {
                    while (flags[0] != 1) { }
                    flags[1] = 1;
                    while (flags[0] != 2) { }
                    .logln("b saw a");
                  }
                }
                """).timeout(TIMEOUT);
        mission.runOn(DeployedInMemory.agents("b")).assertJournal("a saw b\nb saw a\n");
    }
}
