package masl.runtime;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;
import masl.runtime.testing.Driver;
import masl.runtime.testing.MaslProgram;
import masl.runtime.testing.Missions;
import masl.runtime.testing.TestAgent;
import masl.runtime.testing.Watching;
import masl.runtime.trace.JsonLinesTrace;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * External invocations (MASL §5, §9): the caller waits for the result without holding a thread,
 * the callee serves at its boundaries or, blocked, on its behalf; a primitive's exception becomes
 * {@code uncaught_exception} in the caller, whose call then gives the default value.
 */
@Timeout(120)
class ExternalInvocationTest {

    static final int ROUNDS = 3;

    /**
     * Two agents in one synchronous block call each other {@link #ROUNDS} times, each call an
     * instruction: every call finds the callee awaiting its own call, or at the barrier, and is served.
     */
    private static final MaslProgram MUTUAL = MaslProgram.of("mutual.masl", 2, """
            synchronous entry main (true) {
              local int r;
              for (r = 0; r < %d; r++) {
                if (.getProxyID() == 0) .logln("0 saw " + a1.getProxyID()); else .logln("1 saw " + a0.getProxyID());
              }
            }
            """.formatted(ROUNDS));

    @ParameterizedTest
    @EnumSource(Driver.class)
    void twoAgentsCallingEachOtherInASynchronousBlockNeverDeadlock(Driver driver) {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            StringWriter trace = new StringWriter();
            String journal = MUTUAL.run(driver.newScheduler(), new JsonLinesTrace(trace)).journal();
            assertEquals(List.of("0 saw 1", "0 saw 1", "0 saw 1", "1 saw 0", "1 saw 0", "1 saw 0"),
                    journal.lines().sorted().toList(), journal);
            assertTrue(trace.toString().contains(
                    "\"event\":\"invocation-made\",\"requester\":0,\"callee\":1,\"member\":\"getProxyID\""),
                    trace::toString);
            assertTrue(trace.toString().contains(
                    "\"event\":\"invocation-served\",\"requester\":1,\"callee\":0,\"member\":\"getProxyID\""),
                    trace::toString);
        }
    }

    /**
     * Agent 0 invokes {@code divide} of {@code target}, which throws; agent 1 is parked at the exit
     * barrier by then, or not yet there.
     */
    private static final String THROWING = """
            synchronous entry main (true) {
              local int v = 7;
              local Default target = %s;
              if (.getProxyID() == 0) { v = target.divide(1, 0); .logln("v=" + v); }
              react (uncaught_exception) { .logln(getMessageFromEvent(uncaught_exception)); resume; }
            }
            """;

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aPrimitivesExceptionBecomesUncaughtExceptionInTheCallerWithTheDefaultValue(Driver driver) {
        MaslProgram throwing = MaslProgram.of("throwing.masl", 2, THROWING.formatted("a1"));
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            // The reaction at the call's step boundary, then the value: the type's default.
            assertEquals("java.lang.ArithmeticException\nv=0\n", throwing.run(driver).journal());
        }
    }

    /** {@code a.m()} with {@code a} holding no agent: as a Java call that throws, not a failed mission. */
    @ParameterizedTest
    @EnumSource(Driver.class)
    void invokingAnAgentVariableHoldingNullIsAnUncaughtException(Driver driver) {
        MaslProgram throwing = MaslProgram.of("throwing.masl", 2, THROWING.formatted("null"));
        assertEquals("java.lang.NullPointerException\nv=0\n", throwing.run(driver).journal());
    }

    /**
     * Agent 0 calls agent 1 while agent 1 is stuck at a barrier of {@code pair}, waiting for agent
     * 2, which busy-waits until that call has been answered: only serving on the callee's behalf lets
     * the mission end. Agent 0 spins until agent 2 loops and agent 1 is parked ({@code signal(1)}
     * answers 1 once agent 1 is idle).
     */
    private static final MaslProgram STUCK_CALLEE = MaslProgram.of("stuck.masl", 3, """
            asynchronous entry main (true) {
              shared int looping = 0;
              shared int served = 0;
              shared int arrived = 0;
              arrived++;
              while (arrived < 3) {}
              synchronous entry pair (.getProxyID() != 0) {
                .nop();
                if (.getProxyID() == 1) .nop();
                else { looping = 1; while (served == 0) {} .nop(); }
              }
              if (.getProxyID() == 0) {
                while (looping == 0 || .signal(1) == 0) {}
                .logln("served " + a1.getProxyID());
                served = 1;
              }
            }
            """);

    @ParameterizedTest
    @EnumSource(Driver.class)
    void aCalleeStuckAtASynchronisationBarrierServesItsCaller(Driver driver) throws InterruptedException {
        for (int run = 0; run < Missions.REPETITIONS; run++) {
            List<TestAgent> agents = new ArrayList<>();
            AtomicReference<Mission> mission = new AtomicReference<>();
            BooleanSupplier calleeParked = () -> mission.get().agentOf(agents.get(1)).isIdle();
            mission.set(STUCK_CALLEE.newMission(MaslProgram.recording(() -> new Watching(calleeParked), agents))
                    .scheduler(driver.newScheduler()).build());
            assertEquals("served 1\n", mission.get().run(Duration.ofSeconds(20)).requireCompleted().journal());
        }
    }
}
