package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.Missions;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** Entry members (MASL §6.7) through one wave of a synchronous block, as §6.4 counts them. */
@Timeout(120)
class EntryMembersTest {

    /** What the keeper sees of {@code gate}, and of {@code main} where {@code %s} stands. */
    private static final String LOOK = "\"count=\" + gate.count + \" list=\" + masl.runtime.testing.ProxyIds.of(gate.getList())"
            + " + \" in=\" + gate.getWaitingInCount() + masl.runtime.testing.ProxyIds.of(gate.getWaitingInList())"
            + " + \" active=\" + gate.getActiveCount() + masl.runtime.testing.ProxyIds.of(gate.getActiveList())"
            + " + \" out=\" + gate.getWaitingOutCount() + masl.runtime.testing.ProxyIds.of(gate.getWaitingOutList())"
            + " + \" \" + gate.getLockPolicy()%s";
    private static final String WITH_MAIN = LOOK.formatted(
            " + \" | main count=\" + main.count + \" active=\" + main.getActiveCount() + \" \" + main.getLockPolicy()");
    private static final String GATE_ONLY = LOOK.formatted("");

    /**
     * A keeper lets agents 1 and 2 into a locked synchronous block one at a time, then lets
     * agent 1 finish (it waits out) and then agent 2, and logs what it sees of the members at each stage.
     */
    private static final MaslProgram WATCHED = MaslProgram.of("members.masl", 3, """
            Entry gate;
            asynchronous entry main (true) {
              shared int go1 = 0;
              shared int go2 = 0;
              scalar entry setup (true) { gate.lock(); }
              while (gate.getLockPolicy() == "free") {}
              asynchronous entry keep (.getProxyID() == 0) {
                while (gate.getWaitingInCount() < 2) {}
                .logln(%1$s); gate.release(1); .logln(%1$s); gate.release(1); .logln(%1$s);
                go1 = 1;
                while (gate.getWaitingOutCount() < 1) {}
                .logln(%1$s); go2 = 1;
                while (gate.count > 0) {}
                .logln(%2$s);
              }
              synchronous entry gate (.getProxyID() != 0) {
                while ((.getProxyID() == 1 ? go1 : go2) == 0) {}
              }
            }
            """.formatted(WITH_MAIN, GATE_ONLY));

    @ParameterizedTest
    @EnumSource(Driver.class)
    void membersAreCountedByStateThroughAWave(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            List<String> seen = WATCHED.run(driver).journal().lines().toList();
            // Held agents are members of gate and main; only gate's own barriers make them inactive
            // in gate: in main they are active (they still have gate to run, §6.4).
            assertEquals("count=2 list=[1, 2] in=2[1, 2] active=0[] out=0[] locked | main count=3 active=3 unavailable", seen.get(0));
            assertEquals(List.of("in=1 active=1 out=0", "in=0 active=2 out=0"),
                    List.of(part(seen.get(1)), part(seen.get(2))));
            assertEquals("count=2 list=[1, 2] in=0[] active=2[1, 2] out=0[] locked | main count=3 active=3 unavailable", seen.get(2));
            assertEquals("count=2 list=[1, 2] in=0[] active=1[2] out=1[1] locked | main count=3 active=3 unavailable", seen.get(3));
            assertEquals("count=0 list=[] in=0[] active=0[] out=0[] locked", seen.get(4));
        }
    }

    private static String part(String look) {
        return look.replaceAll(".* in=(\\d+)\\[.*\\] active=(\\d+)\\[.*\\] out=(\\d+)\\[.*", "in=$1 active=$2 out=$3");
    }
}
