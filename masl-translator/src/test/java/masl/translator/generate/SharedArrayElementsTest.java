package masl.translator.generate;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import masl.runtime.scheduling.PoolScheduler;
import org.junit.jupiter.api.Test;

/**
 * Element stores into an array a shared variable holds ({@code reports[i] = …}, MASL §7): the
 * generated store is Java's, on the array {@code get()} gives, and tells the variable which element it
 * stored, so that a deployed agent's copy of the variable can have the owner store it; each index is
 * evaluated once; the values the stores have are Java's.
 */
class SharedArrayElementsTest {

    private static final String TEAM = """
            import Default.xml as Default;
            Default a, b, c = newAgent(Default);
            synchronous entry main (true) {
              shared String[] reports = new String[main.count];
              shared int[][] grid = new int[2][3];
              local int i = 1;
              reports[.getProxyID()] = "agent " + .getProxyID();
              reports[.getProxyID()] = reports[.getProxyID()] + "!";
              grid[1][.getProxyID()] += 2 + i;
              grid[0][.getProxyID()]++;
              scalar entry report (true) {
                local int before = grid[0][0]++;
                local int after = ++grid[0][0];
                local int set = (grid[1][0] = 7);
                .logln(String.join(",", reports) + " " + grid[0][0] + grid[0][1] + grid[0][2] + " " + grid[1][1]
                    + " " + before + after + set + " " + reports.length);
              }
            }
            """;

    @Test
    void anElementStoreTellsTheVariableWhichElementItStored() {
        String program = Programs.translate("team.masl", TEAM).javaSources().get("masl.generated.team.DefaultProgram");
        assertTrue(program.contains("ctx.shared(MAIN_REPORTS).stored(ctx.shared(MAIN_REPORTS).get()[tmp$1 = "
                + "invokeSelf$getProxyID(ctx)] = \"agent \" + invokeSelf$getProxyID(ctx), tmp$1);"), program);
        assertTrue(program.contains("ctx.shared(MAIN_GRID).stored(ctx.shared(MAIN_GRID).get()[1][tmp$3 = "
                + "invokeSelf$getProxyID(ctx)] += 2 + main$i, 1, tmp$3);"), program);
        assertTrue(program.contains("ctx.shared(MAIN_GRID).stored(++ctx.shared(MAIN_GRID).get()[0][tmp$4 = "
                + "invokeSelf$getProxyID(ctx)], 0, tmp$4);"), program);
        // In an expression, a postfix's value is the element before; the one after is read from the same array.
        assertTrue(program.contains("report$before = ((int) ctx.shared(MAIN_GRID).postfixStored((tmp$5 = "
                + "ctx.shared(MAIN_GRID).get())[0][0]++, tmp$5[0][0], 0, 0));"), program);
        String mission = Programs.translate("team.masl", TEAM).javaSources().get("masl.generated.team.TeamMission");
        assertTrue(mission.contains("SharedDeclaration<String[]> MAIN_REPORTS = MAIN.declareSharedArray(\"reports\","
                + " String[].class);"), mission);
    }

    @Test
    void elementStoresGiveJavasValuesAndEveryAgentsElement() {
        String journal = Programs.journal(Programs.load(TEAM), new PoolScheduler());
        assertEquals("agent 0!,agent 1!,agent 2! 311 3 137 3\n", journal);
    }

    /**
     * A busy-wait loop (MASL §5) parks until something it can observe changes: an element stored by
     * another agent is such a change, or the two agents below, each waiting for the other's element,
     * were found deadlocked.
     */
    @Test
    void aBusyWaitLoopWakesWhenAnotherAgentStoresTheElementItWaitsFor() {
        String journal = Programs.journal(Programs.load(HANDSHAKE), new PoolScheduler());
        assertEquals("seen\nanswered\n", journal);
    }

    static final String HANDSHAKE = """
            import Default.xml as Default;
            Default a, b = newAgent(Default);
            asynchronous entry main (true) {
              shared int[] flags = new int[1];
              if (.getProxyID() == 0) {
                flags[0] = 1;
                while (flags[0] != 2) { }
                .logln("answered");
              } else {
                while (flags[0] == 0) { }
                .logln("seen");
                flags[0] = 2;
              }
            }
            """;
}
