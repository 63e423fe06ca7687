package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLongArray;
import masl.runtime.scheduling.Scheduler;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.MemoryTrace;
import masl.runtime.trace.Trace;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** {@code wait(state)} and {@code wait(state, ms)} (MASL §11). */
@Timeout(120)
class AttentiveWaitTest {

    /**
     * The server (agent 0) waits in state {@code onlyLog}, which lets only its group invoke
     * {@code log}. Agent 2, outside the group, launches the server's {@code measure} first; then
     * agent 1, in the group, invokes {@code log}.
     */
    private static final MaslProgram ONLY_LOG = MaslProgram.of("onlylog.masl", 3, """
            asynchronous entry main (true) {
              shared int asked = 0;
              local int id = 0;
              asynchronous entry group (.getProxyID() <= 1) {
                if (.getProxyID() == 0) { wait("onlyLog", 2000); .logln("after wait"); }
                else { while (asked == 0) {} a0.log("log from 1\\n"); }
              }
              if (.getProxyID() == 2) {
                id = a0.measure();
                asked = 1;
                .logln("got " + id);
              }
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aWaitServesTheAllowedInvocationAndLeavesTheOthersQueuedUntilAfter(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            String journal = ONLY_LOG.run(driver.newScheduler(), trace).journal();
            assertTrue(journal.startsWith("log from 1\n"), journal);
            assertEquals(List.of("0 measures", "after wait", "got 0", "log from 1"), journal.lines().sorted().toList(), journal);
            assertEquals(List.of("log by 1", "measure by 2"), trace.events(TraceEvent.InvocationServed.class).stream()
                    .map(served -> served.member() + " by " + served.requester()).toList(), "served in this order");
        }
    }

    /**
     * Agent 0 waits in state {@code nothing} for 300 ms, taking the mission clock before and after
     * ({@code signal(0)}, {@code signal(1)}); agent 1 invokes its {@code signal(2)} meanwhile, which
     * runs only after the wait. Nothing stands between agent 0's entry and its wait that takes time,
     * so no step boundary serves the call before the wait begins.
     */
    private static final MaslProgram NOTHING = MaslProgram.of("nothing.masl", 2, """
            asynchronous entry main (true) {
              if (.getProxyID() == 0) { .signal(0); wait("nothing", 300); .signal(1); }
              else { a0.signal(2); .logln("answered"); }
            }
            """);

    /** Takes the time of the mission's clock at each {@code signal(k)} as the {@code k}-th time. */
    private static final class Clocked extends TestAgent {
        private final Scheduler clock;
        private final AtomicLongArray times;

        Clocked(Scheduler clock, AtomicLongArray times) {
            this.clock = clock;
            this.times = times;
        }

        @Override
        public int signal(int moment) {
            times.set(moment, clock.nanoTime());
            return moment;
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aWaitThatNothingSatisfiesEndsByItsTimeout(Driver driver) {
        for (int run = 0; run < 3; run++) {
            AtomicLongArray times = new AtomicLongArray(3);
            Scheduler scheduler = driver.newScheduler();
            String journal = NOTHING.run(scheduler, Trace.NONE, () -> new Clocked(scheduler, times)).journal();
            long waited = times.get(1) - times.get(0);
            assertTrue(waited >= TimeUnit.MILLISECONDS.toNanos(300), "waited " + waited + " ns");
            assertTrue(waited < TimeUnit.SECONDS.toNanos(15), "waited " + waited + " ns");
            long served = times.get(2) - times.get(0);
            assertTrue(served >= TimeUnit.MILLISECONDS.toNanos(300), "served " + served + " ns after the wait began");
            assertEquals("answered\n", journal, "the queued call was answered after the wait");
        }
    }
}
