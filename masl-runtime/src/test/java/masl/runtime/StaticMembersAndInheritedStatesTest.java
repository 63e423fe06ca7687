package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.Missions;
import masl.runtime.trace.MemoryTrace;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Permeability of a subtype (MASL §11): agent 0, a {@code TestRobot}, starts in the state
 * {@code default} it inherits, takes its own state {@code censusBySelf} (static {@code census}:
 * rights 100), then the inherited {@code x0}. Agent 1 (a {@code TestRobot} too) and agent 2 (a
 * {@code TestAgent}), both outside agent 0's block, invoke {@code census} of agent 0 in each state:
 * in {@code censusBySelf} only the requester of the same type runs it (the u digit, §11's rule for
 * static members); in {@code x0}, which lists no rights for {@code census}, nobody does.
 * Each requester logs what its two calls returned: {@code census} gives 1, a denied call the default 0.
 */
@Timeout(120)
class StaticMembersAndInheritedStatesTest {

    private static final MaslProgram CENSUS = MaslProgram.of("census.masl", """
            import Default.xml as Default;
            import TestRobot.xml as TestRobot;
            TestRobot r0, r1 = newAgent(TestRobot);
            Default t2 = newAgent(Default);
            asynchronous entry main (true) {
              shared int phase = 0;
              shared int done = 0;
              local int first = 0;
              local int second = 0;
              asynchronous entry own (.getProxyID() == 0) {
                .logln(getAcceptState()); setAcceptState("censusBySelf"); phase = 1; while (done < 2) {}
                setAcceptState("x0"); phase = 2; while (done < 4) {}
                setAcceptState("default");
              }
              if (.getProxyID() != 0) {
                while (phase < 1) {}
                first = r0.census();
                done++;
                while (phase < 2) {}
                second = r0.census();
                done++;
                .logln(.getProxyID() + ": " + first + " " + second);
              }
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aStaticMemberIsFilteredByUForItsOwnTypeAndStatesAreInherited(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            List<String> journal = CENSUS.runOfDeclaredClasses(driver.newScheduler(), trace).journal().lines().toList();
            assertEquals("default", journal.get(0));
            assertEquals(List.of("1: 1 0", "2: 0 0"), journal.subList(1, 3).stream().sorted().toList(),
                    "census runs: only by the same type, only in censusBySelf");
            assertEquals(List.of("1 x0", "2 censusBySelf", "2 x0"), trace.events(TraceEvent.InvocationDenied.class).stream()
                    .map(denied -> denied.requester() + " " + denied.state()).sorted().toList());
        }
    }
}
