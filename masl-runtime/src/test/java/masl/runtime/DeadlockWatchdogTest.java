package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;
import java.util.regex.Pattern;
import masl.runtime.scheduling.ThreadPerAgentScheduler;
import masl.runtime.scheduling.WakeUps;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.TestAgent;
import masl.runtime.testing.Watching;
import masl.runtime.testing.TestTypes;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The deadlock watchdog (see {@link Mission}): it never reports a mission whose agents all look
 * parked while a thread is between deciding to wake one and the wake-up being visible (that thread is
 * stalled there, by the watchdog's accounting {@link StallingWakeUps}, until the watchdog has looked
 * at the quiet mission three times, more than the two agreeing looks a report needs), and it still
 * reports a wait that no queued invocation can end.
 */
@Timeout(60)
class DeadlockWatchdogTest {

    /**
     * Agent 0 waits in state {@code default} (attentive, no timeout) and, once an invocation has
     * ended its wait, logs and finishes. Agent 1 awaits {@code released}, then finishes. No block.
     * {@code beforeParking} runs in the slice that parks, {@code woken} in the one after.
     * Written by hand: these hooks stand between two runtime calls of one slice, where no MASL statement can.
     */
    static final class WaitOrAwait extends AgentProgram {
        private final TestAgent self;
        private final CompletableFuture<Void> released;
        private final Runnable beforeParking;
        private final Runnable woken;

        WaitOrAwait(TestAgent self, CompletableFuture<Void> released, Runnable beforeParking, Runnable woken) {
            this.self = self;
            this.released = released;
            this.beforeParking = beforeParking;
            this.woken = woken;
        }

        @Override
        @SuppressWarnings("fallthrough") // resumption points fall through into the next one
        protected void resume(AgentContext ctx) {
            switch (pc) {
                case 0:
                    pc = 1;
                    boolean goOn = self.getProxyID() == 0 ? ctx.waitFor("default") : ctx.await(released);
                    if (!goOn) {
                        beforeParking.run();
                        return;
                    }
                case 1:
                    woken.run();
                    if (self.getProxyID() == 0) {
                        self.logln("wait ended");
                    }
                    ctx.finish();
                    return;
                default:
                    throw new IllegalStateException("pc " + pc);
            }
        }
    }

    /** Stalls the first wake-up counted on thread {@link #stalled} right after its count. */
    static final class StallingWakeUps extends WakeUps {
        volatile Thread stalled;
        /** When the mission is quiet but for the stalled wake-up; null until known. */
        volatile BooleanSupplier quietButForTheStall;
        final CountDownLatch inTheWindow = new CountDownLatch(1);
        /** Counted by the watchdog's looks (two reads each) at the quiet mission: three looks. */
        final CountDownLatch quietLooks = new CountDownLatch(6);
        /** Counted by looks while the agents are parked (the submission may begin). */
        final CountDownLatch parkedLooks = new CountDownLatch(1);
        volatile BooleanSupplier parked;

        @Override
        public void counted() {
            super.counted();
            if (Thread.currentThread() == stalled && inTheWindow.getCount() > 0) {
                inTheWindow.countDown();
                awaitUninterruptibly(quietLooks);
            }
        }

        @Override
        public long look() {
            BooleanSupplier quiet = quietButForTheStall;
            if (inTheWindow.getCount() == 0 && quiet != null && quiet.getAsBoolean()) {
                quietLooks.countDown();
            }
            BooleanSupplier allParked = parked;
            if (allParked != null && allParked.getAsBoolean()) {
                parkedLooks.countDown();
            }
            return super.look();
        }

        void release() {
            while (quietLooks.getCount() > 0) {
                quietLooks.countDown();
            }
        }
    }

    private static void awaitUninterruptibly(CountDownLatch latch) {
        boolean interrupted = false;
        while (true) {
            try {
                latch.await();
                break;
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
    }

    /**
     * An invocation from outside the mission (the JADE bridge's path) ends agent 0's wait; its thread
     * stalls after counting the wake-up and before the agent leaves PARKED, while agent 1 finishes.
     */
    @ParameterizedTest
    @EnumSource(value = Driver.class, names = {"POOL", "THREADS", "SEEDED"})
    void anOutsideInvocationStalledBeforeItsServingIsPendingWork(Driver driver) throws Exception {
        StallingWakeUps wakeUps = new StallingWakeUps();
        CompletableFuture<Void> released = new CompletableFuture<>();
        TestAgent waiter = new TestAgent();
        TestAgent awaiter = new TestAgent();
        CountDownLatch awaiterWoken = new CountDownLatch(1);
        Mission mission = Mission.builder().scheduler(driver.newScheduler()).wakeUps(wakeUps)
                .agent("waiter", waiter, TestTypes.testAgent(),
                        self -> new WaitOrAwait(self, released, () -> { }, () -> { }))
                .agent("awaiter", awaiter, TestTypes.testAgent(),
                        self -> new WaitOrAwait(self, released, () -> { }, awaiterWoken::countDown))
                .build();
        wakeUps.parked = () -> mission.agentOf(waiter).isIdle() && mission.agentOf(awaiter).isIdle();
        Thread outside = new Thread(() -> {
            awaitUninterruptibly(wakeUps.parkedLooks);
            mission.submitInvocation(0, () -> waiter.log("served\n"));
        }, "outside");
        wakeUps.stalled = outside;
        Thread choreographer = new Thread(() -> {
            awaitUninterruptibly(wakeUps.inTheWindow);
            // Woken, it finishes without parking again: idle then means done.
            wakeUps.quietButForTheStall = () -> awaiterWoken.getCount() == 0 && mission.agentOf(awaiter).isIdle();
            released.complete(null);
        }, "choreographer");
        outside.start();
        choreographer.start();
        try {
            MissionOutcome outcome = mission.run(Duration.ofSeconds(30));
            assertEquals(MissionOutcome.Status.COMPLETED, outcome.status(), outcome::toString);
            assertEquals("served\nwait ended\n", outcome.journal());
        } finally {
            wakeUps.release();
        }
    }

    /**
     * Agent 0's wait has no invocation to serve when it parks, but agent 1 queues one just before
     * its slice ends; the slice's own thread, about to serve it once the agent is PARKED, stalls
     * after counting the wake-up, while agent 1 finishes.
     */
    @Test
    void theEndOfAWaitingSliceStalledBeforeServingIsPendingWork() throws Exception {
        StallingWakeUps wakeUps = new StallingWakeUps();
        CountDownLatch queued = new CountDownLatch(1);
        TestAgent waiter = new TestAgent();
        TestAgent caller = new TestAgent();
        Runnable waitForTheCall = () -> {
            awaitUninterruptibly(queued);
            wakeUps.stalled = Thread.currentThread();
        };
        Mission mission = Mission.builder().scheduler(new ThreadPerAgentScheduler()).wakeUps(wakeUps)
                .agent("waiter", waiter, TestTypes.testAgent(),
                        self -> new WaitOrAwait(self, new CompletableFuture<>(), waitForTheCall, () -> { }))
                // Written by hand: the latch opens between the invocation and the slice's end, where no MASL statement stands.
                .agent("caller", caller, TestTypes.testAgent(), self -> new AgentProgram() {
                    @Override
                    protected void resume(AgentContext ctx) {
                        ctx.invoke(waiter, "log", null, () -> {
                            waiter.log("served\n");
                            return null;
                        });
                        queued.countDown();
                        ctx.finish();
                    }
                })
                .build();
        wakeUps.quietButForTheStall = () -> mission.agentOf(caller).isIdle();
        try {
            MissionOutcome outcome = mission.run(Duration.ofSeconds(30));
            assertEquals(MissionOutcome.Status.COMPLETED, outcome.status(), outcome::toString);
            assertEquals("served\nwait ended\n", outcome.journal());
        } finally {
            wakeUps.release();
        }
    }

    static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
    static final EntryDefinition HELD = MAIN.child("held", Mode.SYNCHRONOUS);

    /**
     * <pre>
     * asynchronous entry main (true) {
     *   if (me == 0) held.lock();
     *   synchronous entry held (me == 0) { }          // agent 0 waits at its entry
     *   if (me == 1) {
     *     l.x = a0.nop();                             // sets done; queued at agent 0 as its slice ends
     *     while (!done) {}
     *     held.release(1);
     *   }
     * }
     * </pre>
     * Written by hand: agent 0's hook runs in the slice that parks at {@code held}, after the runtime's
     * arrival and before the slice ends, where no MASL statement stands.
     */
    static final class HeldAndReleased extends CompactProgram {
        private final TestAgent held;
        private final AtomicBoolean done;
        /** Agent 0 counts it down as its slice is about to park at {@code held}'s entry barrier. */
        private final CountDownLatch parking;
        /** Agent 0 runs it before parking, agent 1 after queueing {@code setDone}. */
        private final Runnable hook;
        private Label label;

        HeldAndReleased(TestAgent self, TestAgent held, AtomicBoolean done, CountDownLatch parking, Runnable hook) {
            super(self);
            this.held = held;
            this.done = done;
            this.parking = parking;
            this.hook = hook;
        }

        @Override
        @SuppressWarnings("fallthrough") // resumption points fall through into the next one
        protected void resume(AgentContext ctx) {
            int me = self.getProxyID();
            while (true) {
                switch (pc) {
                    case 0: if (!arrive(ctx, MAIN, true, 1, 8)) return; continue;
                    case 1:
                        if (me == 0) {
                            ctx.entry(HELD).lock();
                            if (!arrive(ctx, HELD, true, 2, 3)) {
                                parking.countDown();
                                hook.run();
                                return;
                            }
                            continue;
                        }
                        if (!arrive(ctx, HELD, false, 2, 3)) return;
                        continue;
                    case 2: if (!leave(ctx, HELD, 3)) return; continue;
                    case 3: if (!endOf(ctx, HELD.sequence(), 4)) return; continue;
                    case 4:
                        if (me == 0) {
                            pc = 7;
                            continue;
                        }
                        awaitUninterruptibly(parking);
                        label = ctx.newLabel();
                        label.register(ctx.invoke(held, "nop", null, () -> {
                            done.set(true);
                            return null;
                        }));
                        hook.run();
                        pc = 5;
                        continue;
                    case 5: if (!busyWait(ctx, !done.get(), 6)) return; continue;
                    case 6: ctx.entry(HELD).release(1); if (!step(ctx, 7)) return; continue;
                    case 7: if (!leave(ctx, MAIN, 8)) return; continue;
                    case 8: if (!endOf(ctx, MAIN.sequence(), 9)) return; continue;
                    case 9: ctx.finish(); return;
                    default: throw new IllegalStateException("pc " + pc);
                }
            }
        }
    }

    /**
     * Agent 0, held at an entry barrier, has an invocation queued just before its slice ends; the
     * slice's own thread, about to schedule the serving once the agent is PARKED, stalls after
     * counting, while agent 1 parks in a busy-wait that only the served invocation can end.
     */
    @Test
    void aParkedAgentWithAnInvocationQueuedIsNotIdle() throws Exception {
        StallingWakeUps wakeUps = new StallingWakeUps();
        CountDownLatch parking = new CountDownLatch(1);
        CountDownLatch queued = new CountDownLatch(1);
        AtomicBoolean done = new AtomicBoolean();
        TestAgent held = new TestAgent();
        TestAgent caller = new TestAgent();
        Runnable waitForTheCall = () -> {
            awaitUninterruptibly(queued);
            wakeUps.stalled = Thread.currentThread();
        };
        Mission mission = Mission.builder().main(MAIN).scheduler(new ThreadPerAgentScheduler()).wakeUps(wakeUps)
                .agent("held", held, self -> new HeldAndReleased(self, held, done, parking, waitForTheCall))
                .agent("caller", caller, self -> new HeldAndReleased(self, held, done, parking, queued::countDown))
                .build();
        wakeUps.quietButForTheStall = () -> mission.agentOf(caller).isIdle();
        try {
            MissionOutcome outcome = mission.run(Duration.ofSeconds(30));
            assertEquals(MissionOutcome.Status.COMPLETED, outcome.status(), outcome::toString);
        } finally {
            wakeUps.release();
        }
    }

    /**
     * Agent 0 waits in state {@code nothing}, no timeout; agent 1 spins until agent 0 has parked
     * ({@code signal(1)} answers 1 then: a primitive in the condition makes the loop a spinning one),
     * launches a call it does not allow, and finishes.
     */
    private static final MaslProgram WAIT_FOR_NOTHING = MaslProgram.of("nothing.masl", 2, """
            asynchronous entry main (true) {
              if (.getProxyID() == 0) wait("nothing");
              else { while (.signal(1) == 0) {} a0.measure(); }
            }
            """);

    @Test
    void aWaitNoQueuedInvocationCanEndIsADeadlock() throws InterruptedException {
        List<TestAgent> agents = new ArrayList<>();
        AtomicReference<Mission> mission = new AtomicReference<>();
        BooleanSupplier waiterParked = () -> mission.get().agentOf(agents.get(0)).isIdle();
        mission.set(WAIT_FOR_NOTHING.newMission(MaslProgram.recording(() -> new Watching(waiterParked), agents))
                .scheduler(new ThreadPerAgentScheduler()).build());

        MissionOutcome outcome = mission.get().run(Duration.ofSeconds(30));

        assertEquals(MissionOutcome.Status.DEADLOCKED, outcome.status(), outcome::toString);
        assertTrue(Pattern.compile("agent a0 \\(0\\) at pc \\d+ \\(nothing.masl:4: .*wait\\(\"nothing\"\\).*\\): \\[main\\]\n"
                + "agent a1 \\(1\\) at pc \\d+ .*in no block\n").matcher(outcome.report()).matches(), outcome.report());
    }

    /**
     * The program throws at once. While the runtime names the dying agent for the mission's report
     * ({@code sourceAt}), its state is already DONE but the mission still counts it as running: the
     * program holds its thread there until the watchdog has looked at that quiet mission three times.
     * Written by hand: it holds the runtime inside {@code sourceAt}, which a translated program only answers.
     */
    static final class DiesHeldInTheWindow extends AgentProgram {
        private final BooleanSupplier done;
        private final CountDownLatch inTheWindow;
        private final CountDownLatch looks;

        DiesHeldInTheWindow(BooleanSupplier done, CountDownLatch inTheWindow, CountDownLatch looks) {
            this.done = done;
            this.inTheWindow = inTheWindow;
            this.looks = looks;
        }

        @Override
        protected void resume(AgentContext ctx) {
            throw new IllegalStateException("boom");
        }

        @Override
        protected String sourceAt(int pc) {
            if (done.getAsBoolean() && inTheWindow.getCount() > 0) {
                inTheWindow.countDown();
                awaitUninterruptibly(looks);
            }
            return null;
        }
    }

    /** Counts the watchdog's looks (two reads each) once the dying agent is in the window. */
    static final class LookCounter extends WakeUps {
        volatile CountDownLatch inTheWindow;
        final CountDownLatch looks = new CountDownLatch(6);

        @Override
        public long look() {
            if (inTheWindow != null && inTheWindow.getCount() == 0) {
                looks.countDown();
            }
            return super.look();
        }
    }

    /** A dying agent between its end and the mission's count is not a deadlock: the mission fails with its cause. */
    @ParameterizedTest
    @EnumSource(value = Driver.class, names = {"POOL", "THREADS", "SEEDED"})
    void aDyingAgentHeldBetweenItsEndAndTheMissionsCountIsNoDeadlock(Driver driver) throws Exception {
        LookCounter wakeUps = new LookCounter();
        CountDownLatch inTheWindow = new CountDownLatch(1);
        wakeUps.inTheWindow = inTheWindow;
        TestAgent dier = new TestAgent();
        Mission[] mission = new Mission[1];
        BooleanSupplier done = () -> mission[0].agentOf(dier).isIdle();
        mission[0] = Mission.builder().scheduler(driver.newScheduler()).wakeUps(wakeUps)
                .agent("dier", dier, TestTypes.testAgent(), self -> new DiesHeldInTheWindow(done, inTheWindow, wakeUps.looks))
                .build();
        MissionOutcome outcome = mission[0].run(Duration.ofSeconds(30));
        assertEquals(0, inTheWindow.getCount(), "the agent was never held in the window");
        assertEquals(MissionOutcome.Status.FAILED, outcome.status(), outcome::toString);
        assertEquals("boom", outcome.failure().orElseThrow().getCause().getMessage(), outcome::toString);
    }
}
