package masl.runtime.scheduling;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.stream.IntStream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The pool's run queues and runs of slices, on one worker, where the order of slices is the
 * queues': a wave is one item that keeps its place, a worker's home batches come first, an agent a
 * slice makes runnable runs right after it (32 in a row at most), and what slices defer to the run
 * is done after as many slices as it asks (32 to 4,096), when the queue is empty, and before a slice
 * blocks; and on two, where a busy worker's home batch is not left waiting, and the batch of a short
 * wave stays with the worker whose slice let it go; and agents made runnable together from outside
 * the pool all run, the runner woken for the first and again once the wave is made runnable.
 */
@Timeout(60)
class PoolSchedulerTest {

    private final PoolScheduler scheduler = new PoolScheduler(1);
    private final CountDownLatch gateOpen = new CountDownLatch(1);
    private final List<Integer> ran = new CopyOnWriteArrayList<>();

    @AfterEach
    void shutDown() {
        scheduler.shutdown();
    }

    @Test
    void aWaveRunsInItsOrderBeforeWhatIsScheduledAfterIt() throws InterruptedException {
        CountDownLatch last = new CountDownLatch(1);
        scheduler.schedule(task(-1, this::awaitGate));
        scheduler.scheduleAll(IntStream.range(0, 100).mapToObj(id -> task(id, () -> { })).toList());
        scheduler.schedule(task(100, last::countDown));
        gateOpen.countDown();

        assertTrue(last.await(20, TimeUnit.SECONDS));
        assertEquals(IntStream.rangeClosed(-1, 100).boxed().toList(), ran);
    }

    @Test
    void theRunIsFlushedAfterAChunkOfSlicesAndWhenTheQueueIsEmpty() throws InterruptedException {
        Counting deferred = new Counting(100);
        scheduler.schedule(task(-1, this::awaitGate));
        scheduler.scheduleAll(IntStream.range(0, 100).mapToObj(id -> task(id, () -> defer(deferred))).toList());
        gateOpen.countDown();

        assertTrue(deferred.allFlushed.await(20, TimeUnit.SECONDS));
        assertTrue(deferred.flushes.stream().allMatch(held -> held <= 32), "flushed every 32 slices: " + deferred.flushes);
        assertEquals(100, deferred.flushes.stream().mapToInt(Integer::intValue).sum());
    }

    @Test
    void theRunIsFlushedAfterAsManySlicesAsItsDeferredWorkAsks() throws InterruptedException {
        assertFlushedEvery(100, flushesOf(400, 100, true));
    }

    @Test
    void theRunIsFlushedAfterNoFewerThan32Slices() throws InterruptedException {
        assertFlushedEvery(32, flushesOf(200, 1, false));
    }

    @Test
    void theRunIsFlushedAfterNoMoreThan4096Slices() throws InterruptedException {
        assertFlushedEvery(4_096, flushesOf(10_000, 100_000, true));
    }

    /**
     * Between the first flush (asked for before any work was deferred) and the last (the queue ran
     * empty), each flush held {@code slices} to {@code slices + 31}: the runner looks after each
     * slice it runs alone, and after each chunk of 32 of a wave.
     */
    private static void assertFlushedEvery(int slices, List<Integer> flushes) {
        assertTrue(flushes.size() > 2, "flushes: " + flushes);
        List<Integer> between = flushes.subList(1, flushes.size() - 1);
        assertTrue(between.stream().allMatch(held -> held >= slices && held < slices + 32),
                "flushed every " + slices + " slices: " + flushes);
    }

    /**
     * What each flush found held when {@code slices} slices defer, behind a gate, to work that asks
     * {@code slicesPerFlush}; scheduled as one wave, or one by one (the runner then looks after each
     * slice). Once per test, as a run keeps the deferred work it made first.
     */
    private List<Integer> flushesOf(int slices, int slicesPerFlush, boolean asWave) throws InterruptedException {
        Counting deferred = new Counting(slices);
        deferred.slicesPerFlush = slicesPerFlush;
        CountDownLatch gate = new CountDownLatch(1);
        scheduler.schedule(task(0, () -> {
            defer(deferred);
            await(gate);
        }));
        List<AgentTask> rest = IntStream.range(1, slices).mapToObj(id -> task(id, () -> defer(deferred))).toList();
        if (asWave) {
            scheduler.scheduleAll(rest);
        } else {
            rest.forEach(scheduler::schedule);
        }
        gate.countDown();

        assertTrue(deferred.allFlushed.await(20, TimeUnit.SECONDS));
        assertEquals(slices, deferred.flushes.stream().mapToInt(Integer::intValue).sum());
        return deferred.flushes;
    }

    @Test
    void aSliceAboutToBlockFlushesWhatTheSlicesBeforeItDeferred() throws Exception {
        Counting deferred = new Counting(1);
        CountDownLatch blocked = new CountDownLatch(1);
        List<Boolean> flushedFirst = new ArrayList<>();
        scheduler.scheduleAll(List.of(
                task(0, () -> defer(deferred)),
                task(1, () -> {
                    try {
                        flushedFirst.add(Blocking.call(() -> deferred.allFlushed.await(20, TimeUnit.SECONDS)));
                    } catch (Exception e) {
                        throw new IllegalStateException(e);
                    }
                    blocked.countDown();
                })));

        assertTrue(blocked.await(30, TimeUnit.SECONDS));
        assertEquals(List.of(true), flushedFirst, "the only worker blocked, yet the deferred arrival was done");
    }

    @Test
    void aWorkerRunsTheBatchesOfItsHomeQueueBeforeTheCommonQueue() throws InterruptedException {
        CountDownLatch last = new CountDownLatch(1);
        List<SliceRun> gatedRun = new CopyOnWriteArrayList<>();
        CountDownLatch gated = new CountDownLatch(1);
        scheduler.schedule(task(-1, () -> {
            gatedRun.add(scheduler.currentRun());
            gated.countDown();
            awaitGate();
        }));
        assertTrue(gated.await(20, TimeUnit.SECONDS));
        scheduler.schedule(task(0, last::countDown));
        scheduler.scheduleWoken(batch(gatedRun.get(0), task(1, () -> { })));
        gateOpen.countDown();

        assertTrue(last.await(20, TimeUnit.SECONDS));
        assertEquals(List.of(-1, 1, 0), ran);
    }

    @Test
    void aBatchWhoseHomeWorkerIsBusyIsRunByAnother() throws InterruptedException {
        PoolScheduler two = new PoolScheduler(2);
        try {
            List<SliceRun> busyRun = new CopyOnWriteArrayList<>();
            CountDownLatch busy = new CountDownLatch(1);
            CountDownLatch busyDone = new CountDownLatch(1);
            CountDownLatch ranElsewhere = new CountDownLatch(1);
            two.schedule(task(0, () -> {
                busyRun.add(two.currentRun());
                busy.countDown();
                awaitGate();
                busyDone.countDown();
            }));
            assertTrue(busy.await(20, TimeUnit.SECONDS));
            two.scheduleWoken(batch(busyRun.get(0), task(1, ranElsewhere::countDown)));

            assertTrue(ranElsewhere.await(20, TimeUnit.SECONDS), "the other worker took the batch");
            gateOpen.countDown();
            // Shut down only once the busy slice is over: the pool's shutdown interrupts its workers.
            assertTrue(busyDone.await(20, TimeUnit.SECONDS));
        } finally {
            gateOpen.countDown();
            two.shutdown();
        }
    }

    @Test
    void aBatchOfAShortWaveLetGoByASliceRunsOnThatSlicesWorkerWhateverItsHome() throws InterruptedException {
        PoolScheduler two = new PoolScheduler(2);
        try {
            List<Thread> threads = new CopyOnWriteArrayList<>();
            CountDownLatch batchRan = new CountDownLatch(1);
            SliceRun noWorkersRun = new SliceRun();
            two.schedule(task(0, () -> {
                threads.add(Thread.currentThread());
                two.scheduleWoken(batch(noWorkersRun, task(1, () -> {
                    threads.add(Thread.currentThread());
                    batchRan.countDown();
                })));
            }));

            assertTrue(batchRan.await(20, TimeUnit.SECONDS), "the batch ran");
            assertEquals(threads.get(0), threads.get(1), "on the worker that let it go");
        } finally {
            two.shutdown();
        }
    }

    @Test
    void anAgentHandedOverByASliceThatThenBlocksIsRunMeanwhile() throws Exception {
        CountDownLatch handedOverRan = new CountDownLatch(1);
        List<Boolean> ranWhileBlocked = new CopyOnWriteArrayList<>();
        CountDownLatch done = new CountDownLatch(1);
        scheduler.schedule(task(0, () -> {
            scheduler.schedule(task(1, handedOverRan::countDown));
            try {
                ranWhileBlocked.add(Blocking.call(() -> handedOverRan.await(20, TimeUnit.SECONDS)));
            } catch (Exception e) {
                throw new IllegalStateException(e);
            }
            done.countDown();
        }));

        assertTrue(done.await(30, TimeUnit.SECONDS));
        assertEquals(List.of(true), ranWhileBlocked, "the only runner blocked, yet the agent its slice scheduled ran");
    }

    @Test
    void anAgentASliceMakesRunnableRunsRightAfterThatSlice() throws InterruptedException {
        CountDownLatch last = new CountDownLatch(1);
        scheduler.schedule(task(-1, () -> {
            awaitGate();
            scheduler.schedule(task(5, () -> { }));
        }));
        scheduler.schedule(task(0, () -> { }));
        scheduler.schedule(task(1, last::countDown));
        gateOpen.countDown();

        assertTrue(last.await(20, TimeUnit.SECONDS));
        assertEquals(List.of(-1, 5, 0, 1), ran);
    }

    @Test
    void agentsThatTakeTurnsLetTheQueueInAfterThirtyTwoTurns() throws InterruptedException {
        CountDownLatch queuedRan = new CountDownLatch(1);
        AgentTask[] pair = new AgentTask[2];
        for (int i = 0; i < 2; i++) {
            int other = 1 - i;
            pair[i] = task(10 + i, () -> {
                // Each slice makes the other runnable, as an invocation and its serving slice do, until the queued agent ran.
                if (queuedRan.getCount() > 0) {
                    scheduler.schedule(pair[other]);
                }
            });
        }
        scheduler.schedule(task(-1, () -> {
            awaitGate();
            scheduler.schedule(pair[0]);
        }));
        scheduler.schedule(task(0, queuedRan::countDown));
        gateOpen.countDown();

        assertTrue(queuedRan.await(20, TimeUnit.SECONDS), "the agent in the common queue ran");
        assertEquals(32, ran.indexOf(0) - 1, "turns taken before it: " + ran);
    }

    @Test
    void agentsMadeRunnableTogetherRunAsOneWaveOnceItIsMadeThoughTheRunnerWentIdle() throws InterruptedException {
        CountDownLatch firstRan = new CountDownLatch(1);
        scheduler.schedule(task(0, firstRan::countDown));
        await(firstRan);
        // The runner, with nothing left, waits for work: only the end of the wave wakes it again.
        awaitIdleRunner();
        CountDownLatch allRan = new CountDownLatch(100);
        List<Integer> ranBeforeTheWaveWasMade = new ArrayList<>();
        scheduler.together(() -> {
            IntStream.rangeClosed(1, 100).forEach(id -> scheduler.schedule(task(id, allRan::countDown)));
            ranBeforeTheWaveWasMade.addAll(ran);
        });

        assertEquals(List.of(0), ranBeforeTheWaveWasMade);
        assertTrue(allRan.await(20, TimeUnit.SECONDS), "ran: " + ran);
        assertEquals(IntStream.rangeClosed(0, 100).boxed().toList(), ran);
    }

    @Test
    void noRunOutsideTheSchedulersThreads() {
        assertNull(scheduler.currentRun());
    }

    private void defer(Counting counting) {
        Counting deferred = (Counting) scheduler.currentRun().deferred(run -> counting);
        deferred.held++;
    }

    private static void await(CountDownLatch gate) {
        try {
            assertTrue(gate.await(20, TimeUnit.SECONDS));
        } catch (InterruptedException e) {
            throw new IllegalStateException(e);
        }
    }

    private void awaitIdleRunner() {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (scheduler.idleRunners() == 0) {
            assertTrue(System.nanoTime() < deadline, "the runner never went idle");
            Thread.onSpinWait();
        }
    }

    private void awaitGate() {
        await(gateOpen);
    }

    private AgentTask task(int id, Runnable slice) {
        return new AgentTask() {
            @Override
            public int id() {
                return id;
            }

            @Override
            public void runSlice() {
                ran.add(id);
                slice.run();
            }
        };
    }

    /** A batch of tasks, woken as they are (nothing to wake), at home in {@code home}. */
    private static WokenBatch batch(SliceRun home, AgentTask... tasks) {
        return new WokenBatch() {
            @Override
            public int wake() {
                return tasks.length;
            }

            @Override
            public AgentTask runnable(int index) {
                return tasks[index];
            }

            @Override
            public SliceRun home() {
                return home;
            }

            @Override
            public int wave() {
                return tasks.length;
            }
        };
    }

    /** Deferred work that counts what each flush found held. */
    private static final class Counting implements SliceRun.Deferred {
        final List<Integer> flushes = new CopyOnWriteArrayList<>();
        final CountDownLatch allFlushed;
        int held;
        int slicesPerFlush = SliceRun.DEFAULT_SLICES_PER_FLUSH;

        Counting(int expected) {
            allFlushed = new CountDownLatch(expected);
        }

        @Override
        public boolean flush() {
            if (held == 0) {
                return false;
            }
            flushes.add(held);
            for (int i = 0; i < held; i++) {
                allFlushed.countDown();
            }
            held = 0;
            return true;
        }

        @Override
        public boolean awaitsOthers() {
            return false;
        }

        @Override
        public int slicesPerFlush(int threads) {
            return slicesPerFlush;
        }
    }
}
