package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import masl.runtime.scheduling.ChangeEpoch;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
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
 * a latch that agent 0 opens itself ({@code .signal(k)}), so the moments of completion are the program's.
 */
@Timeout(120)
class LabelTest {

    private static final MaslProgram MEASURES = MaslProgram.of("measures.masl", 4, """
            asynchronous entry main (.getProxyID() == 0) {
              LLabel l;
              local int x1 = 0;
              local int x2 = 0;
              l.x1 = a1.measure(); l.x2 = a2.measure(); l.a3.battery = a3.measure();
              .logln("launched, finished " + l.isFinished());
              .signal(1); .signal(2);
              while (x1 == 0 || x2 == 0) {}
              .logln("two measured, finished " + isFinished(l));
              .signal(3);
              while (!l.isFinished()) {}
              .logln("finished: " + x1 + " " + x2 + " " + a3.battery);
            }
            """);

    /** Measures once agent 0 has opened its gate. */
    private static final class Gated extends TestAgent {
        private final List<CountDownLatch> gates;

        Gated(List<CountDownLatch> gates) {
            this.gates = gates;
        }

        @Override
        public int measure() {
            awaitOpening(gates.get(getProxyID()));
            return 10 * getProxyID();
        }

        @Override
        public int signal(int gate) {
            gates.get(gate).countDown();
            return gate;
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aLabelIsFinishedWhenItsLastInvocationCompletesAndResultsLandWhereAsked(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            List<CountDownLatch> gates = List.of(new CountDownLatch(1), new CountDownLatch(1), new CountDownLatch(1),
                    new CountDownLatch(1));
            String journal = MEASURES.run(driver.newScheduler(), Trace.NONE, () -> new Gated(gates)).journal();
            assertEquals("launched, finished false\ntwo measured, finished false\nfinished: 10 20 30\n", journal);
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
    void aStoreThatFailsStillCountsTheCallAndFailsTheAwait() {
        Label l = new Label(new ChangeEpoch());
        CompletableFuture<Integer> call = new CompletableFuture<>();
        CompletableFuture<Integer> awaited = l.register(call, v -> {
            throw new IllegalStateException("the owner's container is gone");
        });
        call.complete(5);
        assertEquals(List.of(true, true), List.of(l.isFinished(), awaited.isCompletedExceptionally()));
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
