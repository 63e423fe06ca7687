package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.Missions;
import masl.runtime.trace.LeaveCause;
import masl.runtime.trace.MemoryTrace;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The rules of MASL §8 for one agent's processing, each on a small MASL program: priority, the last reaction deciding, lookup in the enclosing blocks,
 * {@code react(default)}, occurrences perceived during processing, {@code clearEvents}, dropping.
 */
@Timeout(120)
class ReactionRulesTest {


    private static final MaslProgram PRIORITY = MaslProgram.of("priority.masl", 1, """
            asynchronous entry main (true) {
              local event x, y, z, go;
              asynchronous entry inner (true) {
                emit(go);
                .logln("end");
                react (z) { .logln("z"); resume; }
                react (y) { .logln("y"); resume; }
              }
              react (x) { .logln("x"); resume; }
              react (go) { emit(x); emit(y); emit(z); resume; }
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void innermostBlockFirstThenReactionsInTheOrderWritten(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            // x, y, z were perceived in this order; inner's reactions come first, z before y as written.
            assertEquals("end\nz\ny\nx\n", PRIORITY.run(driver.newScheduler(), trace).journal());
            assertEquals(List.of("go@main", "z@inner", "y@inner", "x@main"), reactions(trace));
        }
    }

    private static final MaslProgram NEXT_BOUNDARY = MaslProgram.of("next.masl", 1, """
            asynchronous entry main (true) {
              local event ping;
              local int n = 0;
              emit(ping);
              .logln("1");
              .logln("2");
              .logln("3");
              react (ping) { n++; .logln("ping " + n); if (n < 3) emit(ping); resume; }
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void anOccurrencePerceivedDuringProcessingWaitsForTheNextBoundary(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            assertEquals("ping 1\n1\nping 2\n2\nping 3\n3\n", NEXT_BOUNDARY.run(driver).journal());
        }
    }

    /** Two reactions of {@code work} to occurrences queued together, {@code first} written first. */
    private static MaslProgram lastDecides(String name, String first, String second) {
        return MaslProgram.of(name, 1, """
                asynchronous entry main (true) {
                  local event go, leave, stay;
                  asynchronous entry work (true) {
                    emit(go);
                    .logln("stayed");
                    .logln("resumed");
                    %s
                    %s
                  }
                  .logln("after work");
                  react (go) { emit(stay); emit(leave); resume; }
                }
                """.formatted(first, second));
    }

    private static final String REACT_LEAVE = "react (leave) { .logln(\"leave\"); break; }";
    private static final String REACT_STAY = "react (stay) { .logln(\"stay\"); resume; }";
    private static final MaslProgram LEAVE_FIRST = lastDecides("leave-first.masl", REACT_LEAVE, REACT_STAY);
    private static final MaslProgram STAY_FIRST = lastDecides("stay-first.masl", REACT_STAY, REACT_LEAVE);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void theLastReactionRunDecides(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            assertEquals("stayed\nleave\nstay\nresumed\nafter work\n", LEAVE_FIRST.run(driver).journal());
            assertEquals("stayed\nstay\nleave\nafter work\n", STAY_FIRST.run(driver).journal());
        }
    }

    private static final MaslProgram GRAND_PARENT = MaslProgram.of("grandparent.masl", 2, """
            asynchronous entry main (true) {
              local event alarm;
              asynchronous entry top (true) {
                asynchronous entry mid (true) {
                  asynchronous entry inner (true) {
                    emit(alarm);
                    .logln("never");
                  }
                  .logln("never");
                }
                .logln("never");
                react (alarm) { .logln("top reacts"); break; }
              }
              .logln("after top");
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aReactionFoundInTheGrandParentLeavesTheGrandParent(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            String journal = GRAND_PARENT.run(driver.newScheduler(), trace).journal();
            assertEquals(List.of("after top", "after top", "top reacts", "top reacts"), sortedLines(journal));
            for (int agent = 0; agent < 2; agent++) {
                int id = agent;
                assertEquals(List.of("inner:BREAK", "mid:BREAK", "top:BREAK", "main:END"),
                        trace.events(TraceEvent.Left.class).stream().filter(e -> e.agent() == id)
                                .map(e -> e.block() + ":" + e.cause()).toList());
            }
            assertEquals(List.of("alarm@top", "alarm@top"), reactions(trace));
        }
    }

    private static final MaslProgram DEFAULT = MaslProgram.of("default.masl", 1, """
            asynchronous entry main (true) {
              local event a, b;
              asynchronous entry work (true) {
                emitWithMessage(a, "ma");
                emitWithMessage(b, "mb");
                .logln("end");
                react (a) { .logln("a " + getMessageFromEvent(a)); resume; }
                react (default) { .logln("default " + getMessageFromEvent(a) + " " + getMessageFromEvent(b)); resume; }
              }
              react (b) { .logln("main b"); resume; }
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aBlocksDefaultReactionComesBeforeTheParentsReaction(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            // getMessageFromEvent(a) while reacting to b: no occurrence of a is being handled.
            assertEquals("a ma\ndefault null mb\nend\n", DEFAULT.run(driver).journal());
        }
    }

    /** {@code reactToA} ends with {@code clearEvents; resume;} or {@code resume;}. */
    private static MaslProgram clear(String name, String reactToA) {
        return MaslProgram.of(name, 1, """
                asynchronous entry main (true) {
                  local event go, a, b, c;
                  emit(go);
                  .logln("x");
                  .logln("y");
                  react (a) { .logln("a"); %s }
                  react (b) { .logln("b"); break; }
                  react (c) { .logln("c"); break; }
                  react (go) { emit(c); emit(b); emit(a); resume; }
                }
                """.formatted(reactToA));
    }

    private static final MaslProgram CLEARS = clear("clears.masl", "clearEvents; resume;");
    private static final MaslProgram KEEPS = clear("keeps.masl", "resume;");

    @ParameterizedTest
    @EnumSource(Driver.class)
    void clearEventsDropsTheRestSoThatTheCurrentReactionDecides(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            assertEquals("x\na\ny\n", CLEARS.run(driver.newScheduler(), trace).journal());
            assertEquals(List.of("b", "c"), trace.events(TraceEvent.EventDropped.class).stream()
                    .map(TraceEvent.EventDropped::event).toList());
            // Without clearEvents, c runs last and its break leaves main before "y".
            assertEquals("x\na\nb\nc\n", KEEPS.run(driver).journal());
        }
    }

    private static final MaslProgram DROP_AND_LEAVE = MaslProgram.of("drop.masl", 1, """
            asynchronous entry main (true) {
              local event lost, e;
              asynchronous entry work (true) {
                emit(lost);
                .logln("on");
                emit(e);
                .logln("never");
                react (e) { .logln("reacted"); }
              }
              .logln("after work");
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void unhandledOccurrencesAreDroppedAndAReactionWithoutEndingLeavesItsBlock(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            assertEquals("on\nreacted\nafter work\n", DROP_AND_LEAVE.run(driver.newScheduler(), trace).journal());
            assertEquals(List.of("lost"), trace.events(TraceEvent.EventDropped.class).stream()
                    .map(TraceEvent.EventDropped::event).toList());
            assertEquals(List.of("e@work"), reactions(trace));
        }
    }

    private static final MaslProgram RESTART_FROM_REACTION = MaslProgram.of("restart.masl", 1, """
            asynchronous entry main (true) {
              local event again;
              local int k = 0;
              asynchronous entry outer (true) {
                .logln("outer " + k);
                asynchronous entry inner (true) {
                  k++;
                  emit(again);
                  .logln("never");
                }
                .logln("never");
                react (again) { if (k < 3) restart; else break; }
              }
              .logln("done " + k);
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void restartInAReactionRestartsTheReactionsBlock(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            assertEquals("outer 0\nouter 1\nouter 2\ndone 3\n", RESTART_FROM_REACTION.run(driver.newScheduler(), trace).journal());
            assertEquals(List.of("inner:RESTART", "inner:RESTART", "inner:BREAK", "outer:BREAK", "main:END"),
                    trace.events(TraceEvent.Left.class).stream().map(e -> e.block() + ":" + e.cause()).toList());
        }
    }

    private static final MaslProgram REELECT_FROM_REACTION = MaslProgram.of("reelect.masl", 2, """
            asynchronous entry main (true) {
              local event again;
              local int rounds = 0;
              asynchronous entry work (rounds < 2) {
                rounds++;
                emit(again);
                .logln("never");
                react (again) { reelect; }
              }
              .logln("rounds " + rounds);
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void reelectInAReactionArrivesAtTheReactionsBlockAgain(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            assertEquals("rounds 2\nrounds 2\n", REELECT_FROM_REACTION.run(driver.newScheduler(), trace).journal());
            assertEquals(4, trace.events(TraceEvent.Left.class).stream()
                    .filter(e -> e.block().equals("work") && e.cause() == LeaveCause.REELECT).count());
            assertEquals(4, trace.events(TraceEvent.Entered.class).stream().filter(e -> e.block().equals("work")).count());
        }
    }

    /** The reactions run, as {@code event@block of the reaction}, in order. */
    static List<String> reactions(MemoryTrace trace) {
        return trace.events(TraceEvent.EventReacted.class).stream()
                .map(e -> (e.byDefault() ? "default:" : "") + e.event() + "@" + e.block()).toList();
    }

    static List<String> sortedLines(String journal) {
        List<String> lines = new ArrayList<>(Arrays.asList(journal.split("\n")));
        Collections.sort(lines);
        return lines;
    }
}
