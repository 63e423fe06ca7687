package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.fail;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CyclicBarrier;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;
import masl.runtime.scheduling.AgentTask;
import masl.runtime.scheduling.Scheduler;
import masl.runtime.scheduling.ThreadPerAgentScheduler;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * {@link Mission#serveOrQueueInvocation}, the JADE bridge's way of submitting a FIPA request: an
 * agent that is blocked or has finished has the invocation served at once on the submitting thread
 * (no slice of its own), a running one at its next boundary; an invocation racing the wake-up of a
 * parked agent is served exactly once, never while its program runs, and the wake-up is not lost.
 */
@Timeout(120)
class InlineServingTest {

    private static final Duration TIMEOUT = Duration.ofSeconds(20);

    /**
     * Passes every slice to {@code delegate} and counts it once it has returned, so that a test can
     * wait until an agent's slice is over: then the agent is parked, done, or scheduled again.
     */
    private static final class WatchedScheduler implements Scheduler {
        private final Scheduler delegate;
        private final AtomicInteger slices = new AtomicInteger();
        private final Semaphore sliceEnds = new Semaphore(0);
        private AgentTask[] watched;

        WatchedScheduler(Scheduler delegate) {
            this.delegate = delegate;
        }

        @Override
        public void start(List<? extends AgentTask> agents) {
            watched = new AgentTask[agents.size()];
            for (AgentTask agent : agents) {
                watched[agent.id()] = new AgentTask() {
                    @Override
                    public int id() {
                        return agent.id();
                    }

                    @Override
                    public void runSlice() {
                        agent.runSlice();
                        slices.incrementAndGet();
                        sliceEnds.release();
                    }
                };
            }
            delegate.start(List.of(watched));
        }

        @Override
        public long nanoTime() {
            return delegate.nanoTime();
        }

        @Override
        public void schedule(AgentTask agent) {
            delegate.schedule(watched[agent.id()]);
        }

        @Override
        public void scheduleAfter(long delayMillis, Runnable action) {
            delegate.scheduleAfter(delayMillis, action);
        }

        @Override
        public int stepsPerSlice() {
            return delegate.stepsPerSlice();
        }

        @Override
        public void shutdown() {
            delegate.shutdown();
        }

        /** Waits until {@code count} more slices have returned. */
        void awaitSliceEnds(int count) throws InterruptedException {
            sliceEnds.acquire(count);
        }

        /**
         * Waits until {@code condition} holds, looking again each time a slice returns; fails if no
         * slice returns for the mission's timeout (a lost wake-up leaves the agent parked).
         */
        void awaitUntil(BooleanSupplier condition, String what) throws InterruptedException {
            while (!condition.getAsBoolean()) {
                if (!sliceEnds.tryAcquire(TIMEOUT.toMillis(), TimeUnit.MILLISECONDS)) {
                    fail(what);
                }
            }
        }

        int slicesRun() {
            return slices.get();
        }
    }

    /**
     * Agent 0 awaits {@code release}, then logs and finishes; agent 1 finishes at once. Written by
     * hand: each agent's first slice parks or finishes, so that the test counts slices; a MASL
     * program awaits only its own calls, and its entry into {@code main} takes slices of its own.
     */
    private static Mission awaitingAndFinished(Scheduler scheduler, CompletableFuture<Void> release) {
        Mission.Builder builder = Mission.builder().scheduler(scheduler);
        builder.agent("waiting", new TestAgent(), self -> new CompactProgram(self) {
            @Override
            protected void resume(AgentContext ctx) {
                if (pc == 0) {
                    pc = 1;
                    if (!ctx.await(release)) {
                        return;
                    }
                }
                self.logln("released");
                ctx.finish();
            }
        });
        builder.agent("finished", new TestAgent(), self -> new CompactProgram(self) {
            @Override
            protected void resume(AgentContext ctx) {
                ctx.finish();
            }
        });
        return builder.build();
    }

    private static CompletableFuture<MissionOutcome> runInBackground(Mission mission) {
        return CompletableFuture.supplyAsync(() -> {
            try {
                return mission.run(TIMEOUT);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new AssertionError("interrupted", e);
            }
        });
    }

    private static boolean programRunsElsewhere(AtomicReference<Thread> programThread) {
        Thread running = programThread.get();
        return running != null && running != Thread.currentThread();
    }

    private static Runnable denial() {
        return () -> {
            throw new AssertionError("an agent without a type, or in state default, denies nothing");
        };
    }

    @ParameterizedTest
    @EnumSource(value = Driver.class, names = {"POOL", "SINGLE_WORKER", "THREADS"})
    void aBlockedOrFinishedAgentIsServedOnTheSubmittingThreadBeforeTheCallReturns(Driver driver)
            throws Exception {
        WatchedScheduler scheduler = new WatchedScheduler(driver.newScheduler());
        CompletableFuture<Void> release = new CompletableFuture<>();
        Mission mission = awaitingAndFinished(scheduler, release);
        CompletableFuture<MissionOutcome> outcome = runInBackground(mission);
        // Agent 0 has parked on release, agent 1 has finished.
        scheduler.awaitSliceEnds(2);

        List<Thread> servedOn = Collections.synchronizedList(new ArrayList<>());
        mission.serveOrQueueInvocation(0, "nop", () -> servedOn.add(Thread.currentThread()), denial());
        mission.serveOrQueueInvocation(1, "nop", () -> servedOn.add(Thread.currentThread()), denial());

        assertEquals(List.of(Thread.currentThread(), Thread.currentThread()), servedOn);
        assertEquals(2, scheduler.slicesRun(), "no slice was scheduled to serve them");
        release.complete(null);
        MissionOutcome ended = outcome.get();
        assertEquals(MissionOutcome.Status.COMPLETED, ended.status());
        assertEquals("released\n", ended.journal());
    }

    /** The agent's {@code nop} submits an invocation while the agent runs; the step boundary after it serves it. */
    private static final MaslProgram RUNNING = MaslProgram.of("running.masl", 1, """
            scalar entry main (true) { .nop(); .log("boundary"); }
            """);

    /** An agent whose {@code nop} submits an invocation of itself, as the JADE bridge does. */
    private static final class Submitting extends TestAgent {
        private final AtomicReference<Mission> mission;

        Submitting(AtomicReference<Mission> mission) {
            this.mission = mission;
        }

        @Override
        public void nop() {
            log("before ");
            mission.get().serveOrQueueInvocation(0, "nop", () -> log("served "), denial());
            log("after ");
        }
    }

    @Test
    void aRunningAgentServesItAtItsNextBoundaryOnItsOwnThread() throws InterruptedException {
        AtomicReference<Mission> mission = new AtomicReference<>();
        mission.set(RUNNING.newMission(() -> new Submitting(mission)).scheduler(new ThreadPerAgentScheduler()).build());

        MissionOutcome outcome = mission.get().run(TIMEOUT);

        assertEquals(MissionOutcome.Status.COMPLETED, outcome.status());
        assertEquals("before after served boundary", outcome.journal());
    }

    /**
     * Agent 0 parks on {@code releases[0]}, {@code releases[1]}, … in turn. For each, once the agent
     * has parked, one thread completes the future (the unpark) while this one submits an invocation,
     * both let go by a barrier: every interleaving of the inline serve with the wake-up is tried.
     * Written by hand: the program records the thread that runs each of its slices, around the runtime's calls.
     */
    @ParameterizedTest
    @EnumSource(value = Driver.class, names = {"POOL", "SINGLE_WORKER", "THREADS"})
    void anInvocationRacingAnUnparkIsServedOnceAndNeverWhileTheProgramRuns(Driver driver) throws Exception {
        int rounds = 40 * Missions.REPETITIONS;
        List<CompletableFuture<Void>> releases = new ArrayList<>();
        // One more than rounds: the agent finishes only after the last round's invocation is submitted.
        for (int round = 0; round <= rounds; round++) {
            releases.add(new CompletableFuture<>());
        }
        // The thread running the program, null between slices; the program serves at its boundary itself.
        AtomicReference<Thread> programThread = new AtomicReference<>();
        AtomicBoolean serving = new AtomicBoolean();
        AtomicInteger overlaps = new AtomicInteger();
        AtomicInteger served = new AtomicInteger();
        AtomicInteger awaiting = new AtomicInteger(-1);
        WatchedScheduler scheduler = new WatchedScheduler(driver.newScheduler());
        TestAgent agent = new TestAgent();
        Mission mission = Mission.builder().scheduler(scheduler).agent("a", agent,
                self -> new CompactProgram(self) {
                    @Override
                    protected void resume(AgentContext ctx) {
                        programThread.set(Thread.currentThread());
                        if (serving.get()) {
                            overlaps.incrementAndGet();
                        }
                        try {
                            while (pc <= rounds) {
                                CompletableFuture<Void> release = releases.get(pc);
                                awaiting.set(pc);
                                pc++;
                                if (!ctx.await(release)) {
                                    return;
                                }
                            }
                            // A boundary serves what is still queued: a finished agent's invocations may outlive the mission.
                            if (pc == rounds + 1) {
                                pc++;
                                if (!ctx.stepBoundary()) {
                                    return;
                                }
                            }
                            ctx.finish();
                        } finally {
                            programThread.set(null);
                        }
                    }
                }).build();
        CyclicBarrier race = new CyclicBarrier(2);
        Thread unparker = new Thread(() -> {
            try {
                for (CompletableFuture<Void> release : releases.subList(0, rounds)) {
                    race.await();
                    release.complete(null);
                }
            } catch (Exception stopped) {
                Thread.currentThread().interrupt();
            }
        });
        CompletableFuture<MissionOutcome> outcome = runInBackground(mission);
        unparker.start();

        Agent parked = mission.agentOf(agent);
        for (int round = 0; round < rounds; round++) {
            int awaited = round;
            scheduler.awaitUntil(() -> awaiting.get() == awaited && parked.isIdle(),
                    "the agent never parked for round " + round + ": a wake-up was lost");
            race.await();
            mission.serveOrQueueInvocation(0, "nop", () -> {
                if (programRunsElsewhere(programThread) || !serving.compareAndSet(false, true)) {
                    overlaps.incrementAndGet();
                }
                served.incrementAndGet();
                // A primitive takes a while: long enough for a program wrongly let run to be seen.
                for (int spin = 0; spin < 200; spin++) {
                    Thread.onSpinWait();
                }
                if (programRunsElsewhere(programThread)) {
                    overlaps.incrementAndGet();
                }
                serving.set(false);
            }, denial());
        }
        releases.get(rounds).complete(null);
        MissionOutcome ended = outcome.get();
        unparker.join();

        assertEquals(MissionOutcome.Status.COMPLETED, ended.status(), "no wake-up was lost");
        assertEquals(rounds, served.get());
        assertEquals(0, overlaps.get());
    }
}
