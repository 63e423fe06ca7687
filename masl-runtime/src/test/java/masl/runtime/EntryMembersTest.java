package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import java.util.Objects;
import java.util.concurrent.ConcurrentLinkedQueue;
import masl.runtime.entry.Entry;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** Entry members (MASL §6.7) through one wave of a synchronous block, as §6.4 counts them. */
@Timeout(120)
class EntryMembersTest {

    /**
     * A keeper lets agents 1 and 2 into a locked synchronous block one at a time, then lets
     * agent 1 finish (it waits out) and then agent 2, and looks at the members at each stage.
     * <pre>
     * asynchronous entry main (true) {
     *   shared int go1 = 0, go2 = 0;
     *   scalar entry setup (true) { gate.lock(); }
     *   while (gate.getLockPolicy() == "free") {}
     *   asynchronous entry keep (.getProxyID() == 0) {
     *     while (gate.getWaitingInCount() &lt; 2) {}
     *     look(); gate.release(1); look(); gate.release(1); look();
     *     go1 = 1;
     *     while (gate.getWaitingOutCount() &lt; 1) {}
     *     look(); go2 = 1;
     *     while (gate.count > 0) {}
     *     look();
     *   }
     *   synchronous entry gate (.getProxyID() != 0) {
     *     while ((.getProxyID() == 1 ? go1 : go2) == 0) {}
     *   }
     * }
     * </pre>
     */
    static final class Watched extends CompactProgram {
        static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        static final SharedDeclaration<Integer> GO1 = MAIN.declareShared("go1", 0);
        static final SharedDeclaration<Integer> GO2 = MAIN.declareShared("go2", 0);
        static final EntryDefinition SETUP = MAIN.child("setup", Mode.SCALAR);
        static final ESequence KEEP_GATE = MAIN.newSequence();
        static final EntryDefinition KEEP = KEEP_GATE.block("keep", Mode.ASYNCHRONOUS);
        static final EntryDefinition GATE = KEEP_GATE.block("gate", Mode.SYNCHRONOUS);

        private final ConcurrentLinkedQueue<String> looks;

        Watched(TestAgent self, ConcurrentLinkedQueue<String> looks) {
            super(self);
            this.looks = looks;
        }

        @Override
        protected void resume(AgentContext ctx) {
            int id = self.getProxyID();
            Entry gate = ctx.entry(GATE);
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 17)) return; continue;
                    case 1:
                        ctx.shared(GO1).initialise(() -> 0);
                        ctx.shared(GO2).initialise(() -> 0);
                        if (!arrive(ctx, SETUP, true, 2, 3)) return;
                        continue;
                    case 2: gate.lock(); if (!leave(ctx, SETUP, 3)) return; continue;
                    case 3: if (!endOf(ctx, SETUP.sequence(), 4)) return; continue;
                    case 4: if (!busyWait(ctx, Objects.equals(gate.getLockPolicy(), "free"), 5)) return; continue;
                    case 5: if (!arrive(ctx, KEEP, id == 0, 6, 12)) return; continue;
                    case 6: if (!busyWait(ctx, gate.getWaitingInCount() < 2, 7)) return; continue;
                    case 7:
                        look(ctx, true);
                        gate.release(1);
                        look(ctx, true);
                        gate.release(1);
                        look(ctx, true);
                        ctx.shared(GO1).set(1);
                        if (!step(ctx, 8)) return;
                        continue;
                    case 8: if (!busyWait(ctx, gate.getWaitingOutCount() < 1, 9)) return; continue;
                    case 9: look(ctx, true); ctx.shared(GO2).set(1); if (!step(ctx, 10)) return; continue;
                    case 10: if (!busyWait(ctx, gate.count() > 0, 11)) return; continue;
                    case 11: look(ctx, false); if (!leave(ctx, KEEP, 12)) return; continue;
                    case 12: if (!arrive(ctx, GATE, id != 0, 13, 15)) return; continue;
                    case 13:
                        SharedVariable<Integer> go = ctx.shared(id == 1 ? GO1 : GO2);
                        if (!busyWait(ctx, go.get() == 0, 14)) return;
                        continue;
                    case 14: if (!leave(ctx, GATE, 15)) return; continue;
                    case 15: if (!endOf(ctx, KEEP_GATE, 16)) return; continue;
                    case 16: if (!leave(ctx, MAIN, 17)) return; continue;
                    case 17: if (!endOf(ctx, MAIN.sequence(), 18)) return; continue;
                    case 18: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }

        private void look(AgentContext ctx, boolean withMain) {
            Entry gate = ctx.entry(GATE);
            Entry main = ctx.entry(MAIN);
            looks.add("count=" + gate.count() + " list=" + ids(gate.getList())
                    + " in=" + gate.getWaitingInCount() + ids(gate.getWaitingInList())
                    + " active=" + gate.getActiveCount() + ids(gate.getActiveList())
                    + " out=" + gate.getWaitingOutCount() + ids(gate.getWaitingOutList())
                    + " " + gate.getLockPolicy()
                    + (withMain ? " | main count=" + main.count() + " active=" + main.getActiveCount()
                            + " " + main.getLockPolicy() : ""));
        }

        private static List<Integer> ids(List<AgentImplementation> agents) {
            return agents.stream().map(agent -> ((TestAgent) agent).getProxyID()).sorted().toList();
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void membersAreCountedByStateThroughAWave(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            ConcurrentLinkedQueue<String> looks = new ConcurrentLinkedQueue<>();
            Missions.run(driver, Watched.MAIN, 3, self -> new Watched(self, looks));
            List<String> seen = List.copyOf(looks);
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
