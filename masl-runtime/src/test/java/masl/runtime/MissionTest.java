package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.regex.Pattern;
import masl.runtime.scheduling.PoolScheduler;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.LeaveCause;
import masl.runtime.trace.MemoryTrace;
import masl.runtime.trace.Trace;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** Missions: outcomes, journal, contract violations, restart. */
@Timeout(60)
class MissionTest {

    private static final MaslProgram RESTART = MaslProgram.of("restart.masl", MaslProgram.header(2) + """
            asynchronous entry main (true) {
              local int k = 0;
              asynchronous entry b (true) { k++; if (k < 3) restart; }
              .logln(k);
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void restartKeepsMembershipAndLocals(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            assertEquals("3\n3\n", RESTART.run(driver.newScheduler(), trace).journal());
            assertEquals(2, trace.events(TraceEvent.Entered.class).stream().filter(e -> e.block().equals("b")).count());
            assertEquals(List.of(LeaveCause.END, LeaveCause.END), trace.events(TraceEvent.Left.class).stream()
                    .filter(e -> e.block().equals("b")).map(TraceEvent.Left::cause).toList());
        }
    }

    /** A synchronous main whose agents log, then wait at a locked child nobody releases. */
    static final MaslProgram STUCK = MaslProgram.of("stuck.masl", MaslProgram.header(2) + """
            Entry child;
            synchronous entry main (true) {
              .log("x");
              child.lock();
              synchronous entry child (true) { .nop(); }
            }
            """);

    @Test
    void aMissionWhoseAgentsCanNoLongerProgressIsReportedAsDeadlocked() throws InterruptedException {
        StringWriter sink = new StringWriter();
        MissionOutcome outcome = STUCK.newMission(TestAgent::new).journal(sink).build().run(Duration.ofSeconds(30));
        assertEquals(MissionOutcome.Status.DEADLOCKED, outcome.status());
        assertEquals("xx", outcome.journal());
        assertEquals("xx", sink.toString());
        for (int agent = 0; agent < 2; agent++) {
            String line = "agent a%d \\(%d\\) at pc \\d+ \\(stuck.masl:7: synchronous entry child \\(true\\)\\): "
                    + "\\[main, child\\(waiting-in\\)\\]";
            assertTrue(Pattern.compile(line.formatted(agent, agent)).matcher(outcome.report()).find(), outcome.report());
        }
        MissionOutcome.MissionFailedException failure =
                assertThrows(MissionOutcome.MissionFailedException.class, outcome::requireCompleted);
        assertTrue(failure.getMessage().startsWith("mission DEADLOCKED"), failure.getMessage());
    }

    /** Busy, never idle, never done: a loop of instructions ({@code while (true) {}} would be a busy wait, parked). */
    private static final MaslProgram ENDLESS = MaslProgram.of("endless.masl", MaslProgram.header(1) + """
            asynchronous entry main (true) {
              while (true) .nop();
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aMissionThatDoesNotEndInTimeTimesOut(Driver driver) throws InterruptedException {
        Mission mission = ENDLESS.newMission(TestAgent::new).scheduler(driver.newScheduler()).build();
        MissionOutcome outcome = mission.run(Duration.ofMillis(300));
        assertEquals(MissionOutcome.Status.TIMED_OUT, outcome.status());
        assertTrue(Pattern.compile("agent a0 \\(0\\) at pc \\d+ \\(endless.masl:4: .*\\): \\[main\\]").matcher(outcome.report()).find(),
                outcome.report());
    }

    /**
     * The timeout of a mission whose data fills the heap: writing its end finds no room the first
     * time, as when the heap is exhausted, and is written again in the room of the reserve.
     */
    @Test
    void aMissionTimedOutWithTheHeapFullStillRecordsItsEndAndReports() throws InterruptedException {
        MemoryTrace recorded = new MemoryTrace();
        AtomicBoolean heapFull = new AtomicBoolean(true);
        Trace fullAtTheEnd = event -> {
            if (event instanceof TraceEvent.MissionEnded && heapFull.getAndSet(false)) {
                throw new OutOfMemoryError("Java heap space");
            }
            recorded.record(event);
        };
        PoolScheduler scheduler = new PoolScheduler();
        MissionOutcome outcome;
        try {
            outcome = ENDLESS.newMission(TestAgent::new).scheduler(scheduler).trace(fullAtTheEnd).build()
                    .run(Duration.ofMillis(300));
        } catch (OutOfMemoryError escaped) {
            // JUnit would end the whole run on it: an assertion's failure instead, the agent stopped.
            scheduler.shutdown();
            throw new AssertionError("the mission's end found no room, and the mission gave up", escaped);
        }
        assertEquals(MissionOutcome.Status.TIMED_OUT, outcome.status());
        assertEquals(List.of("timed_out"), recorded.events(TraceEvent.MissionEnded.class).stream()
                .map(TraceEvent.MissionEnded::status).toList());
        assertTrue(Pattern.compile("agent a0 \\(0\\) at pc \\d+ \\(endless.masl:4: .*\\): \\[main\\]").matcher(outcome.report()).find(),
                outcome.report());
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aMissionStoppedFromOutsideEndsAsStopped(Driver driver) throws InterruptedException {
        CountDownLatch running = new CountDownLatch(1);
        Mission mission = ENDLESS.newMission(() -> new TestAgent() {
            @Override
            public void nop() {
                running.countDown();
            }
        }).scheduler(driver.newScheduler()).build();
        Thread stopper = new Thread(() -> {
            try {
                running.await();
                mission.stop();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        stopper.start();
        assertEquals(MissionOutcome.Status.STOPPED, mission.run(Duration.ofSeconds(30)).status());
        stopper.join();
    }

    // The programs below break the generated-code contract, or have no main: no MASL program does.

    @Test
    void aProgramThatReturnsWithoutSuspendingFailsTheMission() throws InterruptedException {
        EntryDefinition main = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        MissionOutcome outcome = Mission.builder().main(main)
                .agent("a", new TestAgent(), self -> new AgentProgram() {
                    @Override
                    protected void resume(AgentContext ctx) {
                        pc = 1;
                    }
                })
                .build().run(Duration.ofSeconds(10));
        assertEquals(MissionOutcome.Status.FAILED, outcome.status());
        assertTrue(outcome.failure().orElseThrow().getCause().getMessage()
                .contains("resume returned without a suspension or finish()"));
    }

    @Test
    void aProgramThatThrowsFailsTheMissionWithItsException() throws InterruptedException {
        EntryDefinition main = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        ArithmeticException thrown = new ArithmeticException("/ by zero");
        MissionOutcome outcome = Mission.builder().main(main)
                .agent("a", new TestAgent(), self -> new AgentProgram() {
                    @Override
                    protected void resume(AgentContext ctx) {
                        throw thrown;
                    }
                })
                .build().run(Duration.ofSeconds(10));
        assertEquals(MissionOutcome.Status.FAILED, outcome.status());
        assertEquals(thrown, outcome.failure().orElseThrow().getCause());
    }

    @Test
    void aProgramWithoutMainOnlyCreatesItsAgents() throws InterruptedException {
        MissionOutcome outcome = Mission.builder()
                .agent("a", new TestAgent(), self -> new AgentProgram() {
                    @Override
                    protected void resume(AgentContext ctx) {
                        ctx.finish();
                    }
                })
                .build().run(Duration.ofSeconds(10));
        assertEquals(MissionOutcome.Status.COMPLETED, outcome.status());
        assertEquals("", outcome.journal());
    }

    @Test
    void anImplementationIsBoundToOneAgentOnly() {
        TestAgent shared = new TestAgent();
        Mission.Builder builder = STUCK.newMission(() -> shared);
        assertThrows(IllegalStateException.class, builder::build);
    }

    @Test
    void blocksAreNestedAsTheLanguageAllows() {
        EntryDefinition main = EntryDefinition.main("main", Mode.SCALAR);
        assertThrows(IllegalArgumentException.class, () -> main.child("y", Mode.SYNCHRONOUS));
        assertThrows(IllegalArgumentException.class, () -> main.sequence().block("other", Mode.SCALAR));
        assertEquals(List.of(main.child("s", Mode.SCALAR)), main.children());
    }
}
