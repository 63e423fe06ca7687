package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicReferenceArray;
import masl.runtime.scheduling.ChangeEpoch;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.Trace;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Labels (MASL §10) over asynchronous primitives (§9). Agent 0 launches {@code measure} on agents 1,
 * 2 and 3, which have finished their programs and serve on their behalf; each measure blocks on
 * a latch that agent 0 opens itself, so the moments of completion are the program's.
 * <pre>
 * asynchronous entry main (me == 0) {
 *   LLabel l;
 *   l.x1 = a1.measure(); l.x2 = a2.measure(); l.a3.battery = a3.measure();
 *   seen(l.isFinished());                 // false: nothing measured yet
 *   open(1); open(2); read x1's future; read x2's future;
 *   seen(isFinished(l));                  // false: a3 still measures
 *   open(3); while (!l.isFinished()) {}
 *   seen(x1, x2, a3.battery);
 * }
 * </pre>
 */
@Timeout(120)
class LabelTest {

    static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);

    static final class Measures extends CompactProgram {
        private final AtomicReferenceArray<TestAgent> population;
        private final List<CountDownLatch> gates;
        private final List<String> seen;
        private Label l;
        private int x1;
        private int x2;
        private CompletableFuture<Integer> f1;
        private CompletableFuture<Integer> f2;

        Measures(TestAgent self, AtomicReferenceArray<TestAgent> population, List<CountDownLatch> gates,
                List<String> seen) {
            super(self);
            this.population = population;
            this.gates = gates;
            this.seen = seen;
            population.set(self.getProxyID(), self);
        }

        private Callable<Integer> measure(int agent) {
            return () -> {
                gates.get(agent).await();
                return 10 * agent;
            };
        }

        @Override
        @SuppressWarnings("fallthrough") // resumption points fall through into the next one
        protected void resume(AgentContext ctx) {
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, self.getProxyID() == 0, 1, 8)) return; continue;
                    case 1:
                        l = ctx.newLabel();
                        f1 = l.register(ctx.launch(population.get(1), "measure", 0, measure(1)), v -> x1 = v);
                        f2 = l.register(ctx.launch(population.get(2), "measure", 0, measure(2)), v -> x2 = v);
                        TestAgent a3 = population.get(3);
                        l.register(ctx.launch(a3, "measure", 0, measure(3)), v -> a3.battery = v);
                        seen.add("launched, finished " + l.isFinished());
                        gates.get(1).countDown();
                        gates.get(2).countDown();
                        pc = 2;
                        if (!ctx.await(f1)) return;
                    case 2:
                        pc = 3;
                        if (!ctx.await(f2)) return;
                    case 3:
                        seen.add("two measured, finished " + l.isFinished());
                        gates.get(3).countDown();
                        if (!step(ctx, 4)) return;
                        continue;
                    case 4: if (!busyWait(ctx, !l.isFinished(), 5)) return; continue;
                    case 5:
                        seen.add("finished: " + x1 + " " + x2 + " " + population.get(3).battery);
                        if (!step(ctx, 7)) return;
                        continue;
                    case 7: if (!leave(ctx, MAIN, 8)) return; continue;
                    case 8: if (!endOf(ctx, MAIN.sequence(), 9)) return; continue;
                    case 9: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aLabelIsFinishedWhenItsLastInvocationCompletesAndResultsLandWhereAsked(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            AtomicReferenceArray<TestAgent> population = new AtomicReferenceArray<>(4);
            List<CountDownLatch> gates = List.of(new CountDownLatch(1), new CountDownLatch(1), new CountDownLatch(1),
                    new CountDownLatch(1));
            List<String> seen = new CopyOnWriteArrayList<>();
            Missions.run(driver.newScheduler(), MAIN, 4, null, self -> new Measures(self, population, gates, seen),
                    Trace.NONE);
            assertEquals(List.of("launched, finished false", "two measured, finished false", "finished: 10 20 30"),
                    seen);
        }
    }

    /**
     * A synchronous call through a label is awaited on the future {@code register} gives back
     * (contract §8.3): whoever wakes when that future completes, as {@code ctx.await} does, sees the
     * call counted and its result stored. The raw invocation's own dependants run before the label's
     * (a completing future runs the latest registered first), which is how a caller could go on
     * with the call done but still pending.
     */
    @Test
    void theFutureARegistrationGivesBackCompletesAfterTheCountAndTheStore() {
        Label l = new Label(new ChangeEpoch());
        CompletableFuture<Integer> call = new CompletableFuture<>();
        int[] stored = {0};
        List<String> seenOnWaking = new ArrayList<>();
        CompletableFuture<Integer> awaited = l.register(call, v -> stored[0] = v);
        awaited.whenComplete((v, failure) -> seenOnWaking.add(
                "remaining " + l.getRemainingInvocations() + ", finished " + l.isFinished() + ", stored " + stored[0]));
        call.complete(42);
        assertEquals(List.of("remaining 0, finished true, stored 42"), seenOnWaking);
        assertEquals(42, awaited.join());
    }

    @Test
    void aCompletionAfterFreeIsIgnoredButStillEndsTheAwait() {
        Label l = new Label(new ChangeEpoch());
        CompletableFuture<Integer> call = new CompletableFuture<>();
        int[] stored = {0};
        CompletableFuture<Integer> awaited = l.register(call, v -> stored[0] = v);
        l.register(new CompletableFuture<Integer>());
        assertEquals(2, l.getRemainingInvocations());
        l.free();
        call.complete(7);
        assertEquals(List.of(0, 7, 0), List.of(l.getRemainingInvocations(), awaited.join(), stored[0]));
    }
}
