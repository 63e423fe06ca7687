package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import masl.runtime.descriptor.AgentType;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.runtime.testing.TestTypes;
import masl.runtime.trace.Trace;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Degraded modes (MASL §11): agents drain their battery (an attribute a primitive updates), switch
 * to state {@code degraded} when it falls under 50, and are re-elected into the block whose test
 * reads their state. Agent {@code me} drains 20, 30 or 60 per round.
 * <pre>
 * asynchronous entry main (true) {
 *   battery = 100;
 *   asynchronous entry work (getAcceptState() == "default") {
 *     .drain(amount);
 *     .logln(me + " works at " + battery);
 *     if (battery &lt; 50) setAcceptState("degraded");
 *     reelect;
 *   }
 *   asynchronous entry rest (getAcceptState() == "degraded") {
 *     .logln(me + " degraded at " + battery);
 *   }
 * }
 * </pre>
 */
@Timeout(120)
class DegradedModeTest {

    static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
    static final ESequence MODES = MAIN.newSequence();
    static final EntryDefinition WORK = MODES.block("work", Mode.ASYNCHRONOUS);
    static final EntryDefinition REST = MODES.block("rest", Mode.ASYNCHRONOUS);

    static final class Draining extends CompactProgram {
        private static final int[] AMOUNTS = {20, 30, 60};

        Draining(TestAgent self) {
            super(self);
        }

        private int battery(AgentContext ctx) {
            return ctx.readAttribute(self, "battery", 0, () -> self.battery);
        }

        private void logln(AgentContext ctx, String line) {
            ctx.invokeSelf("logln", null, () -> {
                self.logln(line);
                return null;
            });
        }

        @Override
        @SuppressWarnings("fallthrough") // resumption points fall through into the next one
        protected void resume(AgentContext ctx) {
            int me = self.getProxyID();
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 12)) return; continue;
                    case 1:
                        ctx.writeAttribute(self, "battery", () -> self.battery = 100);
                        if (!step(ctx, 2)) return;
                        continue;
                    case 2: if (!arrive(ctx, WORK, ctx.getAcceptState().equals("default"), 3, 6)) return; continue;
                    case 3:
                        ctx.invokeSelf("drain", 0, () -> self.drain(AMOUNTS[me]));
                        if (!step(ctx, 4)) return;
                        continue;
                    case 4: logln(ctx, me + " works at " + battery(ctx)); if (!step(ctx, 5)) return; continue;
                    case 5:
                        if (battery(ctx) < 50) {
                            ctx.setAcceptState("degraded");
                            if (!step(ctx, 13)) return;
                            continue;
                        }
                        pc = 13;
                        continue;
                    case 13: ctx.reelect(WORK); pc = 2; continue;
                    case 6: if (!arrive(ctx, REST, ctx.getAcceptState().equals("degraded"), 7, 9)) return; continue;
                    case 7: logln(ctx, me + " degraded at " + battery(ctx)); if (!step(ctx, 8)) return; continue;
                    case 8: if (!leave(ctx, REST, 9)) return; continue;
                    case 9: if (!endOf(ctx, MODES, 10)) return; continue;
                    case 10: if (!leave(ctx, MAIN, 11)) return; continue;
                    case 11: if (!endOf(ctx, MAIN.sequence(), 12)) return; continue;
                    case 12: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void agentsSwitchToTheDegradedStateAndAreReelectedIntoItsBlock(Driver driver) {
        AgentType type = TestTypes.testAgent();
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            String journal = Missions.run(driver.newScheduler(), MAIN, 3, type, Draining::new, Trace.NONE).journal();
            assertEquals(List.of("0 works at 80", "0 works at 60", "0 works at 40", "0 degraded at 40"),
                    linesOf(journal, "0 "), journal);
            assertEquals(List.of("1 works at 70", "1 works at 40", "1 degraded at 40"), linesOf(journal, "1 "),
                    journal);
            assertEquals(List.of("2 works at 40", "2 degraded at 40"), linesOf(journal, "2 "), journal);
            assertEquals(9, journal.lines().count(), journal);
        }
    }

    private static List<String> linesOf(String journal, String prefix) {
        return journal.lines().filter(line -> line.startsWith(prefix)).toList();
    }
}
