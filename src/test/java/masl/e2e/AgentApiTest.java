package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import java.util.stream.LongStream;
import masl.runtime.trace.TraceEvent;
import masl.testing.MaslMission;
import masl.testing.MissionRun;
import masl.testing.Schedule;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The agent API from MASL source (contract §8): invocations of other agents'
 * primitives, futures, attributes, permeability, countermeasures and labels, with the Worker type
 * of {@code src/test/resources/workers}. Each mission runs on the pool, with a thread per agent and
 * over seeds of the deterministic scheduler.
 */
@Timeout(60)
class AgentApiTest {

    private static final int RUNS = 20;
    private static final int SEEDS = 100;
    private static final String HEADER = "import workers/Worker.xml;\n";

    static List<Schedule> schedules() {
        return List.of(Schedule.pool(), Schedule.threads());
    }

    @ParameterizedTest
    @MethodSource("schedules")
    void externalSynchronousCallsAndFuturesGiveTheirResults(Schedule schedule) {
        everyRun(schedule, "calls", """
                Worker a, b = newAgent(Worker);
                synchronous entry main (true) {
                  scalar entry ask (true) {
                    local int two = b.twice(20 + 1);
                    local int f = a.slow(5);
                    local int g = b.slow(6);
                    .open(a);
                    .open(b);
                    .logln("two=" + two + " id=" + b.getProxyID() + " sum=" + (f + g));
                  }
                }
                """, run -> run.assertJournal("two=42 id=1 sum=110\n"));
    }

    @ParameterizedTest
    @MethodSource("schedules")
    void mutualExternalCallsInASynchronousBlockComplete(Schedule schedule) {
        everyRun(schedule, "mutual", """
                Worker a, b = newAgent(Worker);
                synchronous entry main (true) {
                  local int got = 0;
                  if (.getProxyID() == 0) got = b.twice(1); else got = a.twice(2);
                  .logln(.getProxyID() + " got " + got);
                }
                """, run -> run.assertLinesInAnyOrder("0 got 2", "1 got 4"));
    }

    @ParameterizedTest
    @MethodSource("schedules")
    void aCalleeWaitingAtABarrierServesTheCall(Schedule schedule) {
        everyRun(schedule, "barrier", """
                Worker a, b, c = newAgent(Worker);
                synchronous entry main (true) {
                  if (.getProxyID() == 0) .logln("a asks " + b.twice(4));
                }
                """, run -> run.assertJournal("a asks 8\n"));
    }

    @ParameterizedTest
    @MethodSource("schedules")
    void attributesOfSelfAndOthersStaticAndConstant(Schedule schedule) {
        everyRun(schedule, "attributes", """
                Worker a, b = newAgent(Worker);
                synchronous entry main (true) {
                  .battery = 10 * (.getProxyID() + 1);
                  if (.getProxyID() == 0) b.battery = b.battery + 5; else .nop();
                  scalar entry once (true) { .made = 7; }
                  .logln(.getProxyID() + ": " + .battery + " " + a.battery + " made=" + b.made + " limit=" + .LIMIT);
                }
                """, run -> run.assertLinesInAnyOrder("0: 10 10 made=7 limit=50", "1: 25 10 made=7 limit=50"));
    }

    @Test
    void assigningAConstantIsAPositionedError() {
        AssertionError error = assertThrows(AssertionError.class, () -> MaslMission.fromString("constant.masl", HEADER + """
                Worker a = newAgent(Worker);
                asynchronous entry main (true) {
                  .LIMIT = 3;
                }
                """).run());
        assertTrue(error.getMessage().contains("constant.masl:4:4: error:"), error.getMessage());
    }

    @ParameterizedTest
    @MethodSource("schedules")
    void waitServesOnlyWhatItsStateAllowsTheRestAfter(Schedule schedule) {
        everyRun(schedule, "wait", """
                Worker server, member, other = newAgent(Worker);
                asynchronous entry main (true) {
                  asynchronous entry group (.getProxyID() != 2) {
                    if (.getProxyID() == 0) {
                      wait("onlyLog", 2000);
                      .logln("waited");
                    } else {
                      server.logln("member");
                    }
                  }
                  asynchronous entry outside (.getProxyID() == 2) {
                    local int id = server.getProxyID();
                    .logln("other got " + id);
                  }
                }
                """, AgentApiTest::assertWait);
    }

    /** The member's logln ends the wait; the other's getProxyID is served after it, by the current state. */
    private static void assertWait(MissionRun run) {
        run.assertLinesInAnyOrder("member", "waited", "other got 0");
        assertEquals("member", run.journalLines().get(0), run::toString);
        List<String> served = new ArrayList<>();
        for (TraceEvent.InvocationServed event : run.trace(TraceEvent.InvocationServed.class)) {
            if (event.callee() == 0 && event.requester() != 0) {
                served.add(event.requester() + " " + event.member());
            }
        }
        assertEquals(List.of("1 logln", "2 getProxyID"), served, run::toString);
    }

    /** Real time, so real schedulers only: the seeded scheduler's clock is virtual. */
    @ParameterizedTest
    @MethodSource("schedules")
    void waitWithATimeoutEndsWhenNothingIsAllowed(Schedule schedule) {
        MaslMission mission = MaslMission.fromString("timeout.masl", HEADER + """
                Worker a = newAgent(Worker);
                asynchronous entry main (true) {
                  local long start = System.nanoTime();
                  wait("nothing", 300);
                  .logln("" + ((System.nanoTime() - start) / 1000000 >= 300));
                }
                """);
        for (int run = 0; run < 3; run++) {
            mission.runWith(schedule).assertJournal("true\n");
        }
    }

    @ParameterizedTest
    @MethodSource("schedules")
    void degradedAgentsAreReelectedIntoTheBlockOfTheirState(Schedule schedule) {
        everyRun(schedule, "degraded", """
                Worker w0, w1, w2 = newAgent(Worker);
                asynchronous entry main (true) {
                  local int amount = 20 + 20 * .getProxyID();
                  asynchronous entry work (getAcceptState() == "default") {
                    .drain(amount);
                    .logln(.getProxyID() + " works at " + .battery);
                    if (.battery < .LIMIT) setAcceptState("degraded");
                    reelect;
                  }
                  asynchronous entry rest (getAcceptState() == "degraded") {
                    .logln(.getProxyID() + " degraded at " + .battery);
                    .drain(1);
                    .logln(.getProxyID() + " still " + .battery);
                    react (timeout) { .logln(.getProxyID() + " refused " + getMessageFromEvent(timeout)); resume; }
                  }
                }
                """, run -> {
                    run.assertLinesInAnyOrder("0 works at 80", "0 works at 60", "0 works at 40", "0 degraded at 40",
                            "0 refused drain", "0 still 40", "1 works at 60", "1 works at 20", "1 degraded at 20",
                            "1 refused drain", "1 still 20", "2 works at 40", "2 degraded at 40", "2 refused drain",
                            "2 still 40");
                    for (int agent = 0; agent < 3; agent++) {
                        String me = agent + " ";
                        List<String> mine = run.journalLines().stream().filter(line -> line.startsWith(me)).toList();
                        assertTrue(mine.get(mine.size() - 3).startsWith(me + "degraded"), run::toString);
                        assertEquals(me + "refused drain", mine.get(mine.size() - 2), run::toString);
                    }
                });
    }

    @ParameterizedTest
    @MethodSource("schedules")
    void countermeasuresFireOnceInnermostFirstUnlessCalledExplicitly(Schedule schedule) {
        everyRun(schedule, "countermeasures", """
                Worker a0, a1, a2, a3, a4 = newAgent(Worker);
                asynchronous entry main (true) {
                  asynchronous entry outer (true) {
                    local event halt;
                    .calibrate();
                    asynchronous entry inner (true) {
                      .calibrate();
                      if (.getProxyID() == 0) break;
                      if (.getProxyID() == 1) break(outer);
                      if (.getProxyID() == 2) emit(halt);
                      if (.getProxyID() == 4) .stopCalibrate();
                    }
                    react (halt) { }
                  }
                }
                """, AgentApiTest::assertCountermeasures);
    }

    private static void assertCountermeasures(MissionRun run) {
        run.assertLinesInAnyOrder("0 stop", "0 stop", "1 stop", "1 stop", "2 stop", "2 stop", "3 stop", "3 stop",
                "4 stop");
        List<List<String>> fired = new ArrayList<>();
        for (int agent = 0; agent < 5; agent++) {
            fired.add(new ArrayList<>());
        }
        for (TraceEvent.CountermeasureFired event : run.trace(TraceEvent.CountermeasureFired.class)) {
            assertEquals("stopCalibrate", event.member());
            fired.get(event.agent()).add(event.block());
        }
        List<String> innermostFirst = List.of("inner", "outer");
        assertEquals(List.of(innermostFirst, innermostFirst, innermostFirst, innermostFirst, List.of()), fired,
                run::toString);
    }

    @ParameterizedTest
    @MethodSource("schedules")
    void aLabelIsFinishedWhenItsLastInvocationCompletesAndStoresEveryResult(Schedule schedule) {
        everyRun(schedule, "label", """
                Worker a, b, c, boss = newAgent(Worker);
                asynchronous entry main (true) {
                  scalar entry collect (.getProxyID() == 3) {
                    LLabel l;
                    local int ra = 0;
                    local int rb = 0;
                    l.ra = a.slow(1);
                    l.rb = b.slow(2);
                    l.c.battery = c.slow(3);
                    .logln("0 " + l.isFinished());
                    .open(a);
                    .logln("1 " + l.isFinished());
                    .open(b);
                    .logln("2 " + isFinished(l));
                    .open(c);
                    while (!l.isFinished()) {}
                    .logln("ra=" + ra + " rb=" + rb + " c=" + c.battery);
                    l.free();
                  }
                }
                """, run -> run.assertJournal("0 false\n1 false\n2 false\nra=10 rb=20 c=30\n"));
    }

    @ParameterizedTest
    @MethodSource("schedules")
    void aSharedLabelCollectsTheWholeWavesInvocations(Schedule schedule) {
        everyRun(schedule, "slabel", """
                Worker a, b, c = newAgent(Worker);
                synchronous entry main (true) {
                  SLabel s;
                  local int mine = 0;
                  s.this.battery = .twice(.getProxyID());
                  s.mine = .slow(.getProxyID() + 1);
                  .open(this);
                  while (!s.isFinished()) {}
                  .logln(.getProxyID() + ": " + .battery + " " + mine);
                }
                """, run -> run.assertLinesInAnyOrder("0: 0 10", "1: 2 20", "2: 4 30"));
    }

    @ParameterizedTest
    @MethodSource("schedules")
    void aMemberTheReceiversTypeLacksIsANopForIt(Schedule schedule) {
        everyRun(schedule, "polymorphic", """
                import workers/Scout.xml;
                Worker w = newAgent(Worker);
                Worker s = newAgent(Scout);
                synchronous entry main (true) {
                  scalar entry ask (true) {
                    .logln("w=" + w.scan() + " s=" + s.scan() + " ranges " + w.range + " " + s.range);
                    w.range = 9;
                    s.range = s.range + 1;
                    .logln("ranges " + w.range + " " + s.range);
                  }
                }
                """, run -> run.assertJournal("w=0 s=7 ranges 0 3\nranges 0 4\n"));
    }

    @ParameterizedTest
    @MethodSource("schedules")
    void aPrimitivesExceptionGivesTheDefaultValueAndUncaughtException(Schedule schedule) {
        everyRun(schedule, "broken", """
                Worker a, b = newAgent(Worker);
                synchronous entry main (true) {
                  if (.getProxyID() == 0) .logln("got " + b.broken() + " and " + .broken());
                  react (uncaught_exception) { .logln("caught " + getMessageFromEvent(uncaught_exception)); resume; }
                }
                """, run -> run.assertJournal("got 0 and 0\n" + "caught java.lang.IllegalStateException\n".repeat(2)));
    }

    @ParameterizedTest
    @MethodSource("schedules")
    void aCallInAnInitialiserIsAnInstructionReactedToAtItsStepBoundary(Schedule schedule) {
        everyRun(schedule, "initialiser", """
                Worker a = newAgent(Worker);
                scalar entry main (true) {
                  local int got = .broken();
                  .logln("declared " + got);
                  react (uncaught_exception) { .logln("caught"); resume; }
                }
                """, run -> run.assertJournal("caught\ndeclared 0\n"));
    }

    @ParameterizedTest
    @MethodSource("schedules")
    void initialisersCallingInstructionsTakeOneLockStepEachAndAccessorsNone(Schedule schedule) {
        String declarations = """
                  local int id = .getProxyID();
                  local int doubled = .twice(id);
                  local int later = b.slow(id);
                """;
        String plain = declarations.replaceAll("= .*;", "= 0;");
        int withCalls = lockSteps(schedule, "calling", declarations);
        assertEquals(lockSteps(schedule, "plain", plain) + 2, withCalls);
    }

    /** The barrier trips of a synchronous block of two Workers declaring {@code declarations}, the same in every run. */
    private static int lockSteps(Schedule schedule, String name, String declarations) {
        List<Integer> trips = new ArrayList<>();
        everyRun(schedule, name, "Worker a, b = newAgent(Worker);\nsynchronous entry main (true) {\n"
                + declarations + "  .open(b);\n}\n",
                run -> trips.add(run.assertCompleted().trace(TraceEvent.BarrierTripped.class).size()));
        assertEquals(1, trips.stream().distinct().count(), trips::toString);
        return trips.get(0);
    }

    @ParameterizedTest
    @MethodSource("schedules")
    void agentVariablesAndEntryListElementsAreReceivers(Schedule schedule) {
        everyRun(schedule, "receivers", """
                Worker a, b, c = newAgent(Worker);
                synchronous entry main (true) {
                  scalar entry ask (true) {
                    local Worker w = c;
                    local Worker[] all = main.getList();
                    local int sum = 0;
                    local int i = 0;
                    for (i = 0; i < all.length; i++) { sum += all[i].twice(all[i].getProxyID()); }
                    .logln("w=" + w.twice(5) + " sum=" + sum);
                  }
                }
                """, run -> run.assertJournal("w=10 sum=6\n"));
    }

    private static void everyRun(Schedule schedule, String name, String program, Consumer<MissionRun> property) {
        MaslMission mission = MaslMission.fromString(name + ".masl", HEADER + program);
        for (int run = 0; run < RUNS; run++) {
            property.accept(mission.runWith(schedule));
        }
        if (schedule.equals(Schedule.threads())) {
            mission.explore(LongStream.range(0, SEEDS), 0).assertEveryRun(property);
        }
    }
}
