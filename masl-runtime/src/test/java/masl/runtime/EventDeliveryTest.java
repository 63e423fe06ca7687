package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.List;
import java.util.Map;
import masl.runtime.testing.CompactProgram;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.Missions;
import masl.runtime.testing.PhaseLog;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.LeaveCause;
import masl.runtime.trace.MemoryTrace;
import masl.runtime.trace.Trace;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Who perceives an emission (MASL §8), and events between agents: local and shared events, nested
 * members, concurrent emitters, system events, an abort by event, events in lock-step.
 */
@Timeout(180)
class EventDeliveryTest {


    /**
     * Every emission precedes the last {@code emitted++}, which precedes everyone's {@code .nop()}:
     * an occurrence wrongly delivered to another agent would be reacted to at that boundary at the latest.
     */
    private static final MaslProgram LOCAL_ONLY = MaslProgram.of("local.masl", 3, """
            asynchronous entry main (true) {
              local event mine;
              shared int emitted = 0;
              emitWithMessage(mine, .getProxyID());
              emitted++;
              while (emitted < 3) {}
              .nop();
              react (mine) { .logln(.getProxyID() + " heard " + getMessageFromEvent(mine)); resume; }
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aLocalEventIsPerceivedByItsEmitterOnly(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            String journal = LOCAL_ONLY.run(driver.newScheduler(), trace).journal();
            assertEquals(List.of("0 heard 0", "1 heard 1", "2 heard 2"), ReactionRulesTest.sortedLines(journal));
            assertTrue(trace.events(TraceEvent.EventEmitted.class).stream().allMatch(e -> e.receivers() == 1));
        }
    }

    private static final MaslProgram SHARED_TO_NESTED = MaslProgram.of("nested.masl", 3, """
            asynchronous entry main (true) {
              shared int ready = 0;
              shared int done = 0;
              asynchronous entry team (.getProxyID() != 2) {
                shared event hello;
                asynchronous entry deep (.getProxyID() == 0) {
                  ready++;
                  while (done == 0) {}
                  .nop();
                }
                if (.getProxyID() == 1) {
                  while (ready < 2) {}
                  emitWithMessage(hello, "hi");
                  done = 1;
                }
                react (hello) { .logln(.getProxyID() + " heard " + getMessageFromEvent(hello)); resume; }
              }
              if (.getProxyID() == 2) {
                ready++;
                while (done == 0) {}
                .nop();
              }
              react (default) { .logln(.getProxyID() + " outside heard"); resume; }
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aSharedEventReachesExactlyTheMembersOfItsBlockIncludingNestedOnes(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            String journal = SHARED_TO_NESTED.run(driver.newScheduler(), trace).journal();
            assertEquals(List.of("0 heard hi", "1 heard hi"), ReactionRulesTest.sortedLines(journal));
            assertEquals(List.of(2), trace.events(TraceEvent.EventEmitted.class).stream()
                    .map(TraceEvent.EventEmitted::receivers).toList());
        }
    }

    private static final int EMITTERS = 8;
    private static final int EMISSIONS = 50;

    /** Each agent emits {@code EMISSIONS} occurrences; every agent logs each it receives, as "receiver emitter:i". */
    private static final MaslProgram CONCURRENT_EMISSION = MaslProgram.of("concurrent.masl", EMITTERS, """
            asynchronous entry main (true) {
              shared event ping;
              shared int inside = 0;
              shared int done = 0;
              local int i = 0;
              inside++;
              while (inside < %d) {}
              for (i = 0; i < %d; i++) emitWithMessage(ping, .getProxyID() + ":" + i);
              done++;
              while (done < %d) {}
              .nop();
              react (ping) { .logln(.getProxyID() + " " + getMessageFromEvent(ping)); resume; }
            }
            """.formatted(EMITTERS, EMISSIONS, EMITTERS));

    @ParameterizedTest
    @EnumSource(Driver.class)
    void concurrentEmittersLoseNothingAndEachEmittersOrderIsKept(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            List<String> journal = CONCURRENT_EMISSION.run(driver).journal().lines().toList();
            for (int receiver = 0; receiver < EMITTERS; receiver++) {
                String prefix = receiver + " ";
                List<String> received = journal.stream().filter(line -> line.startsWith(prefix))
                        .map(line -> line.substring(prefix.length())).toList();
                assertEquals(EMITTERS * EMISSIONS, received.size());
                int[] next = new int[EMITTERS];
                for (String message : received) {
                    String[] parts = message.split(":");
                    int emitter = Integer.parseInt(parts[0]);
                    assertEquals(next[emitter]++, Integer.parseInt(parts[1]), "order of emitter " + emitter);
                }
            }
        }
    }

    private static final MaslProgram UNCAUGHT = MaslProgram.of("uncaught.masl", 2, """
            asynchronous entry main (true) {
              local int q = 7;
              q = .divide(1, 0);
              .logln("q=" + q);
              react (uncaught_exception) { .logln("caught " + getMessageFromEvent(uncaught_exception)); resume; }
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void anExceptionOfAPrimitiveBecomesUncaughtExceptionAndTheMissionGoesOn(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            assertEquals(List.of("caught java.lang.ArithmeticException", "caught java.lang.ArithmeticException",
                    "q=0", "q=0"), ReactionRulesTest.sortedLines(UNCAUGHT.run(driver).journal()));
        }
    }

    private static final MaslProgram ABORT = MaslProgram.of("abort.masl", 4, """
            asynchronous entry main (true) {
              shared event abort;
              shared int working = 0;
              asynchronous entry work (.getProxyID() != 0) {
                working++;
                while (true) { .nop(); }
                react (abort) { .logln("worker " + .getProxyID() + " stops"); break; }
              }
              asynchronous entry boss (.getProxyID() == 0) {
                while (working < 3) {}
                emit(abort);
              }
              .logln("left " + .getProxyID());
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aTeamAbortsInterruptibleWorkWithAnEvent(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            String journal = ABORT.run(driver).journal();
            assertEquals(List.of("left 0", "left 1", "left 2", "left 3",
                    "worker 1 stops", "worker 2 stops", "worker 3 stops"), ReactionRulesTest.sortedLines(journal));
            for (int worker = 1; worker <= 3; worker++) {
                assertTrue(journal.indexOf("worker " + worker + " stops") < journal.indexOf("left " + worker), journal);
            }
        }
    }

    /** Instructions {@code i1 … i4} go to one {@link PhaseLog}, reactions (their {@code logln}) to another. */
    private static final MaslProgram LOCK_STEP_TICK = MaslProgram.of("tick.masl", 3, """
            synchronous entry main (true) {
              shared event tick;
              .instruction("i1");
              if (.getProxyID() == 0) emitWithMessage(tick, .instruction("i2")); else .instruction("i2");
              .instruction("i3");
              .instruction("i4");
              react (tick) { .logln("tick"); resume; }
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void reactionsInLockStepHappenAtTheEmissionsBoundaryOrTheNextOne(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            // A reaction is not an instruction: it shares its phase with the instruction before it,
            // so reactions are logged apart, against the same barrier trips.
            PhaseLog ticks = new PhaseLog("main", Trace.NONE);
            PhaseLog instructions = new PhaseLog("main", ticks);
            String journal = LOCK_STEP_TICK.run(driver.newScheduler(), instructions, () -> new TestAgent(instructions) {
                @Override
                public void logln(String message) {
                    super.logln(message);
                    ticks.instruction(getProxyID(), message);
                }
            }).journal();
            assertEquals("tick\ntick\ntick\n", journal);
            assertEquals(List.of(), instructions.lockStepViolations());
            for (int agent = 0; agent < 3; agent++) {
                Map<String, Integer> mine = instructions.phases().get(agent);
                assertEquals(List.of(0, 1, 2, 3),
                        List.of(mine.get("i1"), mine.get("i2"), mine.get("i3"), mine.get("i4")));
                int tick = ticks.phases().get(agent).get("tick");
                assertTrue(tick == 1 || tick == 2, "agent " + agent + " reacted in phase " + tick);
            }
            assertEquals(1, ticks.phases().get(0).get("tick"), "the emitter reacts at its own boundary");
        }
    }

    private static final MaslProgram WAKE_UP = MaslProgram.of("wakeup.masl", 2, """
            asynchronous entry main (true) {
              shared event go;
              shared int listening = 0;
              shared int acknowledged = 0;
              local boolean heard = false;
              asynchronous entry talk (.getProxyID() == 0) {
                while (listening == 0) {}
                emit(go);
                while (acknowledged == 0) {}
              }
              asynchronous entry listen (.getProxyID() == 1) {
                listening = 1;
                while (!heard) {}
                acknowledged = 1;
                react (go) { heard = true; resume; }
              }
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void anEventWakesAnAgentParkedInABusyWait(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            WAKE_UP.run(driver.newScheduler(), trace);
            assertEquals(List.of("go@listen"), ReactionRulesTest.reactions(trace));
        }
    }

    /** Every member reacts at the boundary of the emission or of {@code w3}: nobody logs {@code w4}. */
    private static final MaslProgram BREAK_IN_LOCK_STEP = MaslProgram.of("break.masl", 3, """
            synchronous entry main (true) {
              synchronous entry work (true) {
                shared event stop;
                .log("w1 ");
                if (.getProxyID() == 0) emit(stop); else .nop();
                .log("w3 ");
                .log("w4 ");
                react (stop) { break; }
              }
              .logln("after");
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aReactionsBreakOutOfASynchronousBlockIsNotWaitedFor(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            String journal = BREAK_IN_LOCK_STEP.run(driver.newScheduler(), trace).journal();
            assertEquals(3, journal.split("w1 ", -1).length - 1, journal);
            assertEquals(3, journal.split("after\n", -1).length - 1, journal);
            assertTrue(!journal.contains("w4"), journal);
            assertEquals(3, trace.events(TraceEvent.Left.class).stream()
                    .filter(e -> e.block().equals("work") && e.cause() == LeaveCause.BREAK).count());
        }
    }

    private static final MaslProgram HELD_MEMBER = MaslProgram.of("held.masl", 2, """
            Entry gate;
            asynchronous entry main (true) {
              shared event open;
              shared int inside = 0;
              inside++;
              while (inside < 2) {}
              asynchronous entry talk (.getProxyID() == 0) {
                while (gate.getWaitingInCount() == 0) {}
                emitWithMessage(open, "now");
              }
              .nop();
              synchronous entry gate (.getProxyID() == 1) {
                .logln("in gate");
              }
              react (open) { .logln(.getProxyID() + " heard " + getMessageFromEvent(open)); resume; }
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void anAgentHeldByAnEntryBarrierPerceivesButReactsOnlyOnceLetIn(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            String journal = HELD_MEMBER.run(driver.newScheduler(), trace).journal();
            assertEquals(List.of("0 heard now", "1 heard now", "in gate"), ReactionRulesTest.sortedLines(journal));
            assertTrue(journal.indexOf("in gate") < journal.indexOf("1 heard now"), journal);
            assertEquals(List.of(2), trace.events(TraceEvent.EventEmitted.class).stream()
                    .map(TraceEvent.EventEmitted::receivers).toList());
        }
    }

    /**
     * <pre>
     * asynchronous entry main (true) {
     *   asynchronous entry team (false) { shared event hello; }
     *   emit(hello);             // a compile error in MASL: the runtime refuses it
     * }
     * </pre>
     * Written by hand: the translator rejects this program ({@code hello} is out of scope there), so
     * only a hand-written one reaches the runtime's own check.
     */
    @Test
    void emittingOutsideTheDeclaringBlockFailsTheMission() throws InterruptedException {
        EntryDefinition main = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
        EntryDefinition team = main.child("team", Mode.ASYNCHRONOUS);
        Event hello = team.declareSharedEvent("hello");
        MissionOutcome outcome = Mission.builder().main(main)
                .agent("a", new TestAgent(), self -> new CompactProgram(self) {
                    @Override
                    protected void resume(AgentContext ctx) {
                        while (true) {
                            switch (pc) {
                                case 0: if (!arrive(ctx, main, true, 1, 9)) return; continue;
                                case 1: if (!arrive(ctx, team, false, 2, 3)) return; continue;
                                case 3: if (!endOf(ctx, team.sequence(), 4)) return; continue;
                                case 4: ctx.emit(hello); if (!step(ctx, 5)) return; continue;
                                default: throw new IllegalStateException("pc " + pc);
                            }
                        }
                    }
                })
                .build().run(Duration.ofSeconds(20));
        assertEquals(MissionOutcome.Status.FAILED, outcome.status());
        assertTrue(outcome.failure().orElseThrow().getCause().getMessage()
                .contains("emits shared event hello of team outside that block"), outcome.failure().toString());
    }
}
