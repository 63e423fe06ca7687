package masl.jade.deployment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.List;
import java.util.Map;
import masl.runtime.MissionOutcome;
import masl.runtime.trace.MemoryTrace;
import masl.runtime.trace.TraceEvent;
import masl.testing.jade.DeployedInMemory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * An invocation between two agents deployed to one container, made while the callee is blocked,
 * is served in that container with no message of its own: the mission neither asks the container
 * to run it nor waits for its answer, and still traces it, and its journal is in-process's.
 */
@Timeout(60)
class InvocationsInOneContainerTest {

    private static final Duration TIMEOUT = Duration.ofSeconds(30);

    @Test
    void aCallOfABlockedAgentOfTheSameContainerCostsNoMessageOfItsOwn() throws Exception {
        InMemoryDeployment.Run run = InMemoryDeployment.run(() -> new CallsAtTheBarrier(false),
                Map.of("owner", "c2", "caller", "c2"), TIMEOUT);
        assertTrue(run.outcome().completed(), run.outcome().toString());
        assertEquals(CallsAtTheBarrier.JOURNAL, run.outcome().journal());
        assertEquals(0, run.kinds().getOrDefault("run", 0), run.kinds().toString());
        assertEquals(0, run.kinds().getOrDefault("ran", 0), run.kinds().toString());
        assertEquals(3, run.kinds().getOrDefault("invoked", 0), run.kinds().toString());
    }

    @Test
    void itsJournalAndTraceAreThoseOfInProcess() throws Exception {
        MemoryTrace inProcess = new MemoryTrace();
        MemoryTrace deployed = new MemoryTrace();
        assertEquals(CallsAtTheBarrier.JOURNAL, journal(Map.of(), inProcess));
        assertEquals(CallsAtTheBarrier.JOURNAL, journal(Map.of("owner", "c2", "caller", "c2"), deployed));
        assertEquals(invocations(inProcess), invocations(deployed));
        assertEquals(3, deployed.events(TraceEvent.InvocationServed.class).size());
    }

    /** A primitive served in the container that throws: the caller perceives {@code uncaught_exception}, as in-process. */
    @Test
    void aPrimitiveThatThrowsMakesTheCallerPerceiveUncaughtExceptionAsInProcess() throws Exception {
        MemoryTrace inProcess = new MemoryTrace();
        MemoryTrace deployed = new MemoryTrace();
        assertEquals(CallsAtTheBarrier.JOURNAL_WITH_THROW, journal(Map.of(), inProcess, true));
        assertEquals(CallsAtTheBarrier.JOURNAL_WITH_THROW, journal(Map.of("owner", "c2", "caller", "c2"), deployed,
                true));
        assertEquals(invocations(inProcess), invocations(deployed));
        assertEquals(uncaught(inProcess), uncaught(deployed));
        assertEquals(List.of("emitted 1 java.lang.IllegalArgumentException", "dropped 1"), uncaught(deployed));
    }

    @Test
    void aCallOfAnAgentOfAnotherContainerStillGoesThroughTheMission() throws Exception {
        InMemoryDeployment.Run run = InMemoryDeployment.run(() -> new CallsAtTheBarrier(false),
                Map.of("owner", "c2", "caller", "c3"), TIMEOUT);
        assertEquals(CallsAtTheBarrier.JOURNAL, run.outcome().journal());
        assertEquals(0, run.kinds().getOrDefault("invoked", 0), run.kinds().toString());
        assertEquals(3, run.kinds().getOrDefault("primitive", 0), run.kinds().toString());
    }

    /** A record of an invocation names both its agents, for whom the container that sends it must speak. */
    @Test
    void aContainerVouchesForBothAgentsOfAnInvocationItServed() {
        var record = com.fasterxml.jackson.databind.node.JsonNodeFactory.instance.objectNode()
                .put("kind", "invoked").put("agent", 1).put("callee", 4).put("primitive", "count").put("pc", 1);
        assertEquals(List.of(1, 4), Coordination.agentsNamed(record));
    }

    private static String journal(Map<String, String> deployment, MemoryTrace trace) throws InterruptedException {
        return journal(deployment, trace, false);
    }

    private static String journal(Map<String, String> deployment, MemoryTrace trace, boolean secondThrows)
            throws InterruptedException {
        MissionOutcome outcome = InMemoryDeployment.run(() -> new CallsAtTheBarrier(secondThrows), deployment, trace,
                new DeployedInMemory.Wires(), TIMEOUT).outcome();
        assertTrue(outcome.completed(), outcome.toString());
        return outcome.journal();
    }

    /** What the trace says of {@code uncaught_exception}: who perceived it, with what. */
    private static List<String> uncaught(MemoryTrace trace) {
        return trace.events().stream().map(event -> {
            if (event instanceof TraceEvent.EventEmitted emitted && emitted.event().contains("uncaught")) {
                return "emitted " + emitted.agent() + " " + emitted.message();
            }
            if (event instanceof TraceEvent.EventDropped dropped && dropped.event().contains("uncaught")) {
                return "dropped " + dropped.agent();
            }
            if (event instanceof TraceEvent.EventReacted reacted && reacted.event().contains("uncaught")) {
                return "reacted " + reacted.agent();
            }
            return null;
        }).filter(line -> line != null).toList();
    }

    /** The invocations made and served, with their agents, member and MASL source, in order. */
    private static List<String> invocations(MemoryTrace trace) {
        return trace.events().stream().map(event -> {
            if (event instanceof TraceEvent.InvocationMade made) {
                return "made " + made.requester() + ">" + made.callee() + " " + made.member() + " " + made.source();
            }
            if (event instanceof TraceEvent.InvocationServed served) {
                return "served " + served.requester() + ">" + served.callee() + " " + served.member() + " "
                        + served.source();
            }
            return null;
        }).filter(line -> line != null).toList();
    }
}
