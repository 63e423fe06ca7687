package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.Missions;
import masl.runtime.trace.MemoryTrace;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** Shared variables (MASL §7) and scalar blocks (§6.2). */
@Timeout(120)
class SharedVariableAndScalarTest {

    private static final int INCREMENTS = 1000;

    /**
     * A synchronous main keeps all agents in one wave; the asynchronous child is one instruction
     * of it, in which they increment concurrently; the scalar child reports after the barrier at
     * the end of that instruction.
     */
    private static final MaslProgram COUNTER = MaslProgram.of("counter.masl", MaslProgram.header(64) + """
            synchronous entry main (true) {
              shared int n = 0;
              asynchronous entry count (true) { local int i; for (i = 0; i < %d; i++) n++; }
              scalar entry report (true) { .logln(n); }
            }
            """.formatted(INCREMENTS));

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aSharedCounterIncrementedBy64AgentsAThousandTimesEachEndsAt64000(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            assertEquals(64 * INCREMENTS + "\n", COUNTER.run(driver).journal());
        }
    }

    /**
     * Two groups of four agents run block {@code p} one after the other, so it has two waves;
     * each group stays in {@code p} until all four are in. (The top-level block has one wave, §4,
     * so everyone stays in one wave of main. Main is asynchronous: in a synchronous one the second
     * group's busy-wait would be steps of main, §5, waiting at its barrier for the members of
     * {@code p}, whose one instruction of main {@code p} is, §6.4, while they wait for the second group.)
     */
    private static final MaslProgram SCALAR_PER_PARENT_WAVE = MaslProgram.of("waves.masl", MaslProgram.header(8) + """
            Entry p;
            asynchronous entry main (true) {
              shared int inP = 0;
              while (.getProxyID() >= 4 && (inP < 4 || p.count > inP - 4)) {}   // until the first group left p
              asynchronous entry p (true) {
                inP++;
                while (inP < (.getProxyID() < 4 ? 4 : 8)) {}
                scalar entry once (true) { .logln("once"); }
              }
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aScalarChildRunsOncePerWaveOfItsParent(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            String journal = SCALAR_PER_PARENT_WAVE.run(driver.newScheduler(), trace).journal();
            long parentWaves = trace.events(TraceEvent.WaveStarted.class).stream().filter(w -> w.block().equals("p")).count();
            assertEquals(2, parentWaves);
            assertEquals("once\nonce\n", journal);
            assertEquals(List.of(1, 2), trace.events(TraceEvent.WaveStarted.class).stream()
                    .filter(w -> w.block().equals("once")).map(TraceEvent.WaveStarted::wave).toList());
        }
    }

    /** {@code shared int s = .getProxyID() + 100;} is initialised once, by the first member (the line "init"). */
    private static final MaslProgram INITIALISED_ONCE = MaslProgram.of("once.masl", MaslProgram.header(8) + """
            synchronous entry main (true) {
              shared int s = .logged("init ", .getProxyID() + 100);
              .logged("seen ", s);
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aSharedVariableIsInitialisedOnceBeforeAnyMemberReadsIt(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            List<String> lines = INITIALISED_ONCE.run(driver).journal().lines().toList();
            assertEquals(9, lines.size(), lines::toString);
            String initialisation = lines.get(0);
            assertTrue(initialisation.matches("init 10[0-7]"), initialisation);
            String value = initialisation.substring("init ".length());
            lines.subList(1, 9).forEach(line -> assertEquals("seen " + value, line));
        }
    }

    @Test
    void lockPoliciesFollowTheModes() {
        EntryDefinition main = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        EntryDefinition scalar = main.child("s", Mode.SCALAR);
        EntryDefinition synchronous = main.child("y", Mode.SYNCHRONOUS);
        Mission mission = Mission.builder().main(main).build();
        assertEquals("unavailable", mission.entry(main).getLockPolicy());
        assertEquals("unavailable", mission.entry(scalar).getLockPolicy());
        assertEquals("free", mission.entry(synchronous).getLockPolicy());
        mission.entry(main).lock();
        mission.entry(synchronous).lock();
        assertEquals("unavailable", mission.entry(main).getLockPolicy());
        assertEquals("locked", mission.entry(synchronous).getLockPolicy());
        assertEquals(0, mission.entry(synchronous).count());
        assertEquals(List.of(), mission.entry(synchronous).getList());
    }
}
