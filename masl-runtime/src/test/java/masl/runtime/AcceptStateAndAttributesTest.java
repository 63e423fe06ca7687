package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Objects;
import java.util.concurrent.atomic.AtomicReferenceArray;
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
 * {@code setAcceptState}, {@code getAcceptState()}, {@code getAcceptState(a)} and attribute access
 * under permeability (MASL §9, §11). State {@code readOnly} gives {@code battery} rights 666 with
 * umask 022: the agent reads and writes it, others only read it.
 * <pre>
 * asynchronous entry main (true) {
 *   shared int done = 0;
 *   agent 0: setAcceptState("nope"); .logln("state " + getAcceptState()); battery = 50;
 *            setAcceptState("readOnly"); while (done == 0) {}
 *   agent 1: while (getAcceptState(a0) != "readOnly") {} .logln("read " + a0.battery);
 *            a0.battery = 7; done = 1;
 *   react (uncaught_exception) { .logln(getMessageFromEvent(uncaught_exception)); resume; }
 *   react (forbidden_access) { .logln("forbidden " + getMessageFromEvent(forbidden_access)); resume; }
 * }
 * </pre>
 */
@Timeout(120)
class AcceptStateAndAttributesTest {

    static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
    static final SharedDeclaration<Integer> DONE = MAIN.declareShared("done", 0);
    static final Reaction MAIN_REACT_UNCAUGHT = MAIN.react(Event.UNCAUGHT_EXCEPTION);
    static final Reaction MAIN_REACT_FORBIDDEN = MAIN.react(Event.FORBIDDEN_ACCESS);

    static final class States extends CompactProgram {
        private final AtomicReferenceArray<TestAgent> population;

        States(TestAgent self, AtomicReferenceArray<TestAgent> population) {
            super(self);
            this.population = population;
            population.set(self.getProxyID(), self);
        }

        @Override
        protected int reactionPc(Reaction reaction) {
            if (reaction == MAIN_REACT_UNCAUGHT) {
                return 20;
            }
            return reaction == MAIN_REACT_FORBIDDEN ? 21 : super.reactionPc(reaction);
        }

        @Override
        @SuppressWarnings("fallthrough") // resumption points fall through into the next one
        protected void resume(AgentContext ctx) {
            TestAgent a0 = population.get(0);
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 11)) return; continue;
                    case 1:
                        if (self.getProxyID() != 0) {
                            pc = 6;
                            continue;
                        }
                        ctx.setAcceptState("nope");
                        if (!step(ctx, 2)) return;
                        continue;
                    case 2: self.logln("state " + ctx.getAcceptState()); if (!step(ctx, 3)) return; continue;
                    case 3:
                        ctx.writeAttribute(self, "battery", () -> self.battery = 50);
                        if (!step(ctx, 4)) return;
                        continue;
                    case 4: ctx.setAcceptState("readOnly"); if (!step(ctx, 5)) return; continue;
                    case 5: if (!busyWait(ctx, ctx.shared(DONE).get() == 0, 10)) return; continue;
                    case 6:
                        if (!busyWait(ctx, !Objects.equals(ctx.getAcceptState(a0), "readOnly"), 7)) return;
                        continue;
                    case 7:
                        self.logln("read " + ctx.readAttribute(a0, "battery", -1, () -> a0.battery));
                        if (!step(ctx, 8)) return;
                        continue;
                    case 8:
                        ctx.writeAttribute(a0, "battery", () -> a0.battery = 7);
                        if (!step(ctx, 9)) return;
                        continue;
                    case 9: ctx.shared(DONE).set(1); if (!step(ctx, 10)) return; continue;
                    case 10: if (!leave(ctx, MAIN, 11)) return; continue;
                    case 11: if (!endOf(ctx, MAIN.sequence(), 12)) return; continue;
                    case 12: ctx.finish(); return;
                    case 20:
                        self.logln(ctx.messageOf(Event.UNCAUGHT_EXCEPTION));
                        if (!resumeAfterReaction(ctx)) return;
                        continue;
                    case 21:
                        self.logln("forbidden " + ctx.messageOf(Event.FORBIDDEN_ACCESS));
                        if (!resumeAfterReaction(ctx)) return;
                        continue;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void statesFilterAttributeAccessAndAnUndeclaredStateIsAnUncaughtException(Driver driver) {
        AgentType type = TestTypes.testAgent();
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            AtomicReferenceArray<TestAgent> population = new AtomicReferenceArray<>(2);
            String journal = Missions.run(driver.newScheduler(), MAIN, 2, type,
                    self -> new States(self, population), Trace.NONE).journal();
            assertEquals("java.lang.IllegalArgumentException\nstate default\nread 50\nforbidden battery\n", journal);
            assertEquals(50, population.get(0).battery, "the denied write did not run");
        }
    }
}
