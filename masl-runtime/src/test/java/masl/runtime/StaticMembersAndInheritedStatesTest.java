package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Duration;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.atomic.AtomicIntegerArray;
import java.util.concurrent.atomic.AtomicReferenceArray;
import masl.runtime.descriptor.AgentType;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.runtime.testing.TestRobot;
import masl.runtime.testing.TestTypes;
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
 * <pre>
 * asynchronous entry main (true) {
 *   shared int phase = 0; shared int done = 0;
 *   asynchronous entry own (me == 0) {
 *     log(getAcceptState()); setAcceptState("censusBySelf"); phase = 1; while (done &lt; 2) {}
 *     setAcceptState("x0"); phase = 2; while (done &lt; 4) {}
 *   }
 *   if (me != 0) { while (phase &lt; 1) {} a0.census(); done++; while (phase &lt; 2) {} a0.census(); done++; }
 * }
 * </pre>
 */
@Timeout(120)
class StaticMembersAndInheritedStatesTest {

    static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
    static final SharedDeclaration<Integer> PHASE = MAIN.declareShared("phase", 0);
    static final SharedDeclaration<Integer> DONE = MAIN.declareShared("done", 0);
    static final EntryDefinition OWN = MAIN.child("own", Mode.ASYNCHRONOUS);

    static final class Census extends CompactProgram {
        private final AtomicReferenceArray<TestAgent> population;
        private final AtomicIntegerArray ran;
        private CompletableFuture<Integer> call;

        Census(TestAgent self, AtomicReferenceArray<TestAgent> population, AtomicIntegerArray ran) {
            super(self);
            this.population = population;
            this.ran = ran;
            population.set(self.getProxyID(), self);
        }

        @Override
        @SuppressWarnings("fallthrough") // resumption points fall through into the next one
        protected void resume(AgentContext ctx) {
            int me = self.getProxyID();
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 14)) return; continue;
                    case 1: if (!arrive(ctx, OWN, me == 0, 2, 7)) return; continue;
                    case 2:
                        self.logln(ctx.getAcceptState());
                        ctx.setAcceptState("censusBySelf");
                        ctx.shared(PHASE).set(1);
                        if (!step(ctx, 3)) return;
                        continue;
                    case 3: if (!busyWait(ctx, ctx.shared(DONE).get() < 2, 4)) return; continue;
                    case 4:
                        ctx.setAcceptState("x0");
                        ctx.shared(PHASE).set(2);
                        if (!step(ctx, 5)) return;
                        continue;
                    case 5: if (!busyWait(ctx, ctx.shared(DONE).get() < 4, 6)) return; continue;
                    case 6: if (!leave(ctx, OWN, 7)) return; continue;
                    case 7: if (!endOf(ctx, OWN.sequence(), 8)) return; continue;
                    case 8:
                        if (me == 0) {
                            pc = 13;
                            continue;
                        }
                        if (!busyWait(ctx, ctx.shared(PHASE).get() < 1, 9)) return;
                        continue;
                    case 9:
                        call = ctx.invoke(population.get(0), "census", 0, () -> {
                            ran.incrementAndGet(me);
                            return TestRobot.census();
                        });
                        pc = 10;
                        if (!ctx.await(call)) return;
                    case 10:
                        ctx.shared(DONE).getAndUpdate(done -> done + 1);
                        if (!step(ctx, 11)) return;
                        continue;
                    case 11:
                        if (!busyWait(ctx, ctx.shared(PHASE).get() < 2, 12)) return;
                        continue;
                    case 12:
                        call = ctx.invoke(population.get(0), "census", 0, () -> {
                            ran.addAndGet(me, 10);
                            return TestRobot.census();
                        });
                        pc = 15;
                        if (!ctx.await(call)) return;
                    case 15:
                        ctx.shared(DONE).getAndUpdate(done -> done + 1);
                        if (!step(ctx, 13)) return;
                        continue;
                    case 13: if (!leave(ctx, MAIN, 14)) return; continue;
                    case 14: if (!endOf(ctx, MAIN.sequence(), 16)) return; continue;
                    case 16: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aStaticMemberIsFilteredByUForItsOwnTypeAndStatesAreInherited(Driver driver) throws InterruptedException {
        AgentType robot = TestTypes.testRobot();
        AgentType agent = robot.supertype();
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            AtomicReferenceArray<TestAgent> population = new AtomicReferenceArray<>(3);
            AtomicIntegerArray ran = new AtomicIntegerArray(3);
            MissionOutcome outcome = Mission.builder().main(MAIN).scheduler(driver.newScheduler())
                    .agent("r0", new TestRobot(), robot, self -> new Census(self, population, ran))
                    .agent("r1", new TestRobot(), robot, self -> new Census(self, population, ran))
                    .agent("t2", new TestAgent(), agent, self -> new Census(self, population, ran))
                    .build().run(Duration.ofSeconds(20)).requireCompleted();
            assertEquals("default\n", outcome.journal());
            assertEquals("[0, 1, 0]", ran.toString(), "census runs: only by the same type, only in censusBySelf");
        }
    }
}
