package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Duration;
import java.util.concurrent.atomic.AtomicReference;
import masl.runtime.descriptor.AgentType;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.TestAgent;
import masl.runtime.testing.TestTypes;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * A request from outside the mission (a FIPA agent through the JADE bridge) is an "other" for
 * permeability (MASL §11): agent 0 takes a state, submits such a request for its own {@code nop}
 * through {@link Mission#submitInvocation(int, String, Runnable, Runnable)}, and serves it at its
 * next step boundary: it runs in {@code x1} (o may invoke) and {@code default}, is denied in
 * {@code x6} (only u and g) and {@code nothing}.
 */
@Timeout(120)
class OutsideRequesterTest {

    static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SCALAR);

    /**
     * Written by hand: the request from outside is submitted within the agent's instruction, and
     * the agent logs its state in {@code nothing}, where its own {@code .log} would be denied.
     */
    static final class Requesting extends CompactProgram {
        private final String state;
        private final AtomicReference<Mission> mission;

        Requesting(TestAgent self, String state, AtomicReference<Mission> mission) {
            super(self);
            this.state = state;
            this.mission = mission;
        }

        @Override
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 4)) return; continue;
                    case 1: ctx.setAcceptState(state); if (!step(ctx, 2)) return; continue;
                    case 2:
                        mission.get().submitInvocation(0, "nop", () -> self.log("ran "), () -> self.log("denied "));
                        self.log(ctx.getAcceptState() + ": ");
                        if (!step(ctx, 3)) return;
                        continue;
                    case 3: if (!leave(ctx, MAIN, 4)) return; continue;
                    case 4: if (!endOf(ctx, MAIN.sequence(), 5)) return; continue;
                    case 5: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aRequestFromOutsideIsFilteredAsOther(Driver driver) throws InterruptedException {
        AgentType type = TestTypes.testAgent();
        StringBuilder journals = new StringBuilder();
        for (String state : new String[] {"x1", "default", "x6", "nothing"}) {
            AtomicReference<Mission> mission = new AtomicReference<>();
            mission.set(Mission.builder().main(MAIN).scheduler(driver.newScheduler())
                    .agent("a0", new TestAgent(), type, self -> new Requesting(self, state, mission)).build());
            journals.append(mission.get().run(Duration.ofSeconds(20)).requireCompleted().journal()).append('|');
        }
        assertEquals("x1: ran |default: ran |x6: denied |nothing: denied |", journals.toString());
    }
}
