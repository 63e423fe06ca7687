package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.Missions;
import masl.runtime.testing.PhaseLog;
import masl.runtime.testing.TestAgent;
import masl.runtime.trace.MemoryTrace;
import masl.runtime.trace.Trace;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** Synchronous blocks (MASL §6.3–§6.5): barriers with dynamic membership, entry and exit barriers, waves. */
@Timeout(120)
class SynchronousBlockTest {

    /** Agent {@code k}'s instructions {@code c0}, {@code c1}, … as in {@link PhaseLog}. */
    private static String instructions(String prefix, int count) {
        return IntStream.range(0, count).mapToObj(k -> ".instruction(\"" + prefix + k + "\"); ").collect(Collectors.joining());
    }

    /** A synchronous child of the even agents, {@code c0 … c4}, then {@code m0 … m9} in main. */
    private static final MaslProgram CHILD_IN_LOCK_STEP = MaslProgram.of("child.masl", MaslProgram.header(6) + """
            synchronous entry main (true) {
              synchronous entry child (.getProxyID() %% 2 == 0) { %s}
              %s
            }
            """.formatted(instructions("c", 5), instructions("m", 10)));

    /** As {@link #CHILD_IN_LOCK_STEP}, the child's members breaking out after {@code c2}. */
    private static final MaslProgram BREAK_OUT_OF_CHILD = MaslProgram.of("break.masl", MaslProgram.header(6) + """
            synchronous entry main (true) {
              synchronous entry child (.getProxyID() %% 2 == 0) { %sbreak; }
              %s
            }
            """.formatted(instructions("c", 3), instructions("m", 10)));

    @ParameterizedTest
    @EnumSource(Driver.class)
    void synchronousChildKeepsLockStepWithItsParentsOtherMembers(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            PhaseLog log = new PhaseLog("main", Trace.NONE);
            CHILD_IN_LOCK_STEP.run(driver.newScheduler(), log, () -> new TestAgent(log));
            Map<Integer, Map<String, Integer>> phases = log.phases();
            for (int agent = 0; agent < 6; agent++) {
                Map<String, Integer> phase = phases.get(agent);
                if (agent % 2 == 0) {
                    // Members of the child: c0 … c4 in phases 0 … 4, then m0 … m9 in phases 5 … 14.
                    assertEquals(15, phase.size());
                    for (int k = 0; k < 5; k++) {
                        assertEquals(k, phase.get("c" + k), "agent " + agent + " c" + k);
                    }
                    for (int k = 0; k < 10; k++) {
                        assertEquals(5 + k, phase.get("m" + k), "agent " + agent + " m" + k);
                    }
                } else {
                    // Skippers do not wait for a synchronous child (§6.4): m0 pairs with c0.
                    assertEquals(10, phase.size());
                    for (int k = 0; k < 10; k++) {
                        assertEquals(k, phase.get("m" + k), "agent " + agent + " m" + k);
                    }
                }
            }
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void anAgentBreakingOutOfASynchronousChildKeepsPaceWithoutAnExtraBarrier(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            PhaseLog log = new PhaseLog("main", Trace.NONE);
            BREAK_OUT_OF_CHILD.run(driver.newScheduler(), log, () -> new TestAgent(log));
            Map<Integer, Map<String, Integer>> phases = log.phases();
            for (int agent = 0; agent < 6; agent++) {
                Map<String, Integer> phase = phases.get(agent);
                int firstMainPhase = agent % 2 == 0 ? 3 : 0;
                for (int k = 0; agent % 2 == 0 && k < 3; k++) {
                    assertEquals(k, phase.get("c" + k), "agent " + agent + " c" + k);
                }
                for (int k = 0; k < 10; k++) {
                    assertEquals(firstMainPhase + k, phase.get("m" + k), "agent " + agent + " m" + k);
                }
            }
        }
    }

    /** The odd agents run five instructions in main while the even ones are held at the child's entry barrier. */
    private static final MaslProgram HELD_AT_CHILD_ENTRY = MaslProgram.of("held.masl", MaslProgram.header(6) + """
            Entry child;
            synchronous entry main (true) {
              scalar entry setup (true) { child.lock(); }
              synchronous entry child (.getProxyID() % 2 == 0) { .nop(); .nop(); .nop(); }
              if (.getProxyID() % 2 == 1) {
                .nop(); .nop(); .nop(); .nop();
                if (.getProxyID() == 1) { child.release(); }
                .nop();
              }
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void agentsHeldAtAChildsEntryBarrierDoNotHoldTheParentsBarrier(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            HELD_AT_CHILD_ENTRY.run(driver.newScheduler(), trace);
            List<TraceEvent> events = trace.events();
            int lastHeld = lastIndex(events, e -> e instanceof TraceEvent.WaitingIn w && w.block().equals("child"));
            int firstReleased = firstIndex(events, e -> e instanceof TraceEvent.Released r && r.block().equals("child"));
            List<TraceEvent.BarrierTripped> tripsWhileHeld = new ArrayList<>();
            for (TraceEvent event : events.subList(lastHeld, firstReleased)) {
                if (event instanceof TraceEvent.BarrierTripped trip) {
                    tripsWhileHeld.add(trip);
                }
            }
            // The odd agents' m0 … m3 trip without the three held agents (skipping child takes no step).
            assertEquals(4, tripsWhileHeld.size(), events::toString);
            tripsWhileHeld.forEach(trip -> assertEquals(3, trip.agents(), events::toString));
        }
    }

    /**
     * Agent 0 re-elects itself once; agent 1 lets it in again. {@code reelected = true;} is an
     * instruction of its own, so agent 1 keeps step with it ({@code .nop()}) before it busy-waits:
     * a member busy-waiting in a synchronous block does not arrive at its barrier.
     */
    private static final MaslProgram REELECT_IN_SYNCHRONOUS_BLOCK = MaslProgram.of("reelect.masl", MaslProgram.header(2) + """
            Entry child;
            synchronous entry main (true) {
              synchronous entry child (true) {
                local boolean reelected = false;
                .nop();
                if (.getProxyID() == 0 && !reelected) { reelected = true; reelect; }
                if (.getProxyID() == 1) { .nop(); while (child.getWaitingInCount() == 0) {} child.release(); }
                .nop();
              }
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void reelectLeavesWithoutExitBarrierAndArrivesAgainAsANewArrival(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            REELECT_IN_SYNCHRONOUS_BLOCK.run(driver.newScheduler(), trace);
            List<String> agent0 = new ArrayList<>();
            for (TraceEvent event : trace.events()) {
                if (event instanceof TraceEvent.WaitingIn e && e.agent() == 0 && e.block().equals("child")) {
                    agent0.add("waiting-in");
                } else if (event instanceof TraceEvent.Released e && e.agent() == 0 && e.block().equals("child")) {
                    agent0.add("released into " + e.wave());
                } else if (event instanceof TraceEvent.Left e && e.agent() == 0 && e.block().equals("child")) {
                    agent0.add("left by " + e.cause());
                } else if (event instanceof TraceEvent.WaitingOut e && e.agent() == 0) {
                    agent0.add("waiting-out of " + e.block());
                }
            }
            // The second arrival meets the entry barrier locked by the first wave, is released
            // into that wave (agent 1 is still in it), and its local survived the reelect.
            assertEquals(List.of("waiting-in", "released into 1", "left by REELECT", "waiting-in", "released into 1",
                    "waiting-out of child", "left by END", "waiting-out of main"), agent0);
        }
    }

    static final int MEMBERS = 8;

    /**
     * Agents join a locked synchronous block one by one, as a keeper releases each as soon as it
     * waits, so they join waves in progress; member {@code k} runs {@code 2k + 1} instructions and
     * leaves by its end (even k) or by {@code break} (odd k).
     */
    static final MaslProgram JOIN_AND_LEAVE = MaslProgram.of("join.masl", MaslProgram.header(MEMBERS + 1) + """
            Entry group;
            asynchronous entry main (true) {
              shared int finished = 0;
              scalar entry setup (true) { group.lock(); }
              while (group.getLockPolicy() == "free") {}
              asynchronous entry keep (.getProxyID() == 0) {
                while (finished < %d) { if (group.getWaitingInCount() > 0) group.release(1); }
              }
              synchronous entry group (.getProxyID() != 0) {
                local int k;
                for (k = 0; k < 2 * .getProxyID() + 1; k++) .instruction("g" + k);
                if (.getProxyID() %% 2 == 1) break;
              }
              if (.getProxyID() != 0) finished++;
            }
            """.formatted(MEMBERS));

    @ParameterizedTest
    @EnumSource(Driver.class)
    void agentsJoiningAndLeavingMidWaveNeverDeadlockNorTripWithoutAMember(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            PhaseLog log = new PhaseLog("group", Trace.NONE);
            JOIN_AND_LEAVE.run(driver.newScheduler(), log, () -> new TestAgent(log));
            assertEquals(List.of(), log.lockStepViolations());
            log.trips().forEach(trip -> assertTrue(trip.agents() > 0, trip::toString));
            Map<Integer, Map<String, Integer>> phases = log.phases();
            for (int member = 1; member <= MEMBERS; member++) {
                assertEquals(2 * member + 1, phases.get(member).size(), "instructions of member " + member);
            }
        }
    }

    /**
     * A keeper releases members of a locked block, once {@code waiting} wait, by {@code releases};
     * members log their shared variable.
     */
    private static String gate(int agents, int waiting, String releases) {
        return MaslProgram.header(agents) + """
                Entry gate;
                asynchronous entry main (true) {
                  scalar entry setup (true) { gate.lock(); }
                  while (gate.getLockPolicy() == "free") {}
                  asynchronous entry keep (.getProxyID() == 0) {
                    while (gate.getWaitingInCount() < %d) {}
                    %s
                  }
                  synchronous entry gate (.getProxyID() != 0) {
                    shared int s = 0;
                    .logged("s=", ++s);
                  }
                }
                """.formatted(waiting, releases);
    }

    /** {@code release(n)} first, then all. */
    private static final MaslProgram RELEASE_TWO_THEN_ALL = MaslProgram.of("gate-two.masl", gate(7, 6, """
            gate.release(2);
                .logged("waiting after release ", gate.getWaitingInCount());
                gate.release();"""));

    /** One, and the next one only once the first member's wave is over: only the second agent is left, waiting. */
    private static final MaslProgram RELEASE_ONE_WAVE_EACH = MaslProgram.of("gate-one.masl", gate(3, 2, """
            gate.release(1);
                while (gate.count > 1) {}
                gate.release(1);"""));

    @ParameterizedTest
    @EnumSource(Driver.class)
    void releaseOfNAdmitsExactlyTheNEarliestArrivals(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            String journal = RELEASE_TWO_THEN_ALL.run(driver.newScheduler(), trace).journal();
            assertEquals(List.of("waiting after release 4"),
                    journal.lines().filter(line -> line.startsWith("waiting")).toList(), journal);
            List<Integer> arrivals = trace.events(TraceEvent.WaitingIn.class).stream()
                    .filter(w -> w.block().equals("gate")).map(TraceEvent.WaitingIn::agent).toList();
            List<Integer> released = trace.events(TraceEvent.Released.class).stream()
                    .filter(r -> r.block().equals("gate")).map(TraceEvent.Released::agent).toList();
            assertEquals(6, released.size());
            assertEquals(arrivals.subList(0, 2), released.subList(0, 2));
        }
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void releaseJustAfterAWaveEndsStartsANewWaveWithFreshSharedVariables(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            MemoryTrace trace = new MemoryTrace();
            assertEquals("s=1\ns=1\n", RELEASE_ONE_WAVE_EACH.run(driver.newScheduler(), trace).journal());
            List<String> waves = new ArrayList<>();
            for (TraceEvent event : trace.events()) {
                if (event instanceof TraceEvent.WaveStarted w && w.block().equals("gate")) {
                    waves.add("start " + w.wave());
                } else if (event instanceof TraceEvent.WaveEnded w && w.block().equals("gate")) {
                    waves.add("end " + w.wave());
                } else if (event instanceof TraceEvent.Released r && r.block().equals("gate")) {
                    waves.add("released into " + r.wave());
                }
            }
            assertEquals(List.of("start 1", "released into 1", "end 1", "start 2", "released into 2", "end 2"), waves);
        }
    }

    private static final int STEPS = 1000;

    private static String thousandSteps(int agents) {
        return MaslProgram.header(agents) + """
                synchronous entry main (true) { local int i; for (i = 0; i < %d; i++) .nop(); }
                """.formatted(STEPS);
    }

    /** The scalable model's reason to be: one thread per agent would take about 20 s here. */
    @ParameterizedTest
    @EnumSource(value = Driver.class, names = {"POOL", "SINGLE_WORKER"})
    void aThousandAgentsRunAThousandLockStepSteps(Driver driver) {
        AtomicInteger trips = new AtomicInteger();
        AtomicInteger largestTrip = new AtomicInteger();
        MaslProgram.of("steps.masl", thousandSteps(1000)).run(driver.newScheduler(), event -> {
            if (event instanceof TraceEvent.BarrierTripped trip) {
                trips.incrementAndGet();
                largestTrip.accumulateAndGet(trip.agents(), Math::max);
            }
        });
        assertEquals(STEPS, trips.get());
        assertEquals(1000, largestTrip.get());
    }

    @ParameterizedTest
    @EnumSource(Driver.class)
    void lockStepStepsAtAScaleThreadsCanRun(Driver driver) {
        for (int run = 0; run < 5; run++) {
            AtomicInteger trips = new AtomicInteger();
            MaslProgram.of("steps.masl", thousandSteps(50)).run(driver.newScheduler(), event -> {
                if (event instanceof TraceEvent.BarrierTripped trip && trip.agents() == 50) {
                    trips.incrementAndGet();
                }
            });
            assertEquals(STEPS, trips.get());
        }
    }

    private interface EventTest {
        boolean test(TraceEvent event);
    }

    private static int firstIndex(List<TraceEvent> events, EventTest test) {
        for (int i = 0; i < events.size(); i++) {
            if (test.test(events.get(i))) {
                return i;
            }
        }
        throw new AssertionError("no such event in " + events);
    }

    private static int lastIndex(List<TraceEvent> events, EventTest test) {
        for (int i = events.size() - 1; i >= 0; i--) {
            if (test.test(events.get(i))) {
                return i;
            }
        }
        throw new AssertionError("no such event in " + events);
    }
}
