package masl.runtime.testing;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import masl.runtime.trace.Trace;
import masl.runtime.trace.TraceEvent;

/**
 * Instructions of agents interleaved with the trips of one barrier domain, in the order they
 * happened: a trace of trips and a record of instructions in one list. An instruction recorded by
 * an agent between trips {@code p-1} and {@code p} ran in phase {@code p} (0-based): the agent was
 * let go by trip {@code p-1} and trip {@code p} waited for it.
 */
public final class PhaseLog implements Trace {

    private record Instruction(int agent, String label) { }

    private final String domain;
    private final Trace also;
    private final List<Object> entries = new ArrayList<>();

    /** Records the trips of the domain named {@code domain}; every trace event also goes to {@code also}. */
    public PhaseLog(String domain, Trace also) {
        this.domain = domain;
        this.also = also;
    }

    @Override
    public void record(TraceEvent event) {
        also.record(event);
        if (event instanceof TraceEvent.BarrierTripped trip && trip.domain().equals(domain)) {
            synchronized (this) {
                entries.add(trip);
            }
        }
    }

    /** Called by an agent's program while it runs an instruction. */
    public synchronized void instruction(int agent, String label) {
        entries.add(new Instruction(agent, label));
    }

    /** For each agent, the phase of each of its instructions, by label. */
    public synchronized Map<Integer, Map<String, Integer>> phases() {
        Map<Integer, Map<String, Integer>> phases = new HashMap<>();
        int phase = 0;
        for (Object entry : entries) {
            if (entry instanceof Instruction instruction) {
                phases.computeIfAbsent(instruction.agent(), a -> new HashMap<>()).put(instruction.label(), phase);
            } else {
                phase++;
            }
        }
        return phases;
    }

    /** Agents that ran two instructions between two consecutive trips: never, in lock-step. */
    public synchronized List<String> lockStepViolations() {
        List<String> violations = new ArrayList<>();
        Set<Integer> seen = new HashSet<>();
        int phase = 0;
        for (Object entry : entries) {
            if (entry instanceof Instruction instruction) {
                if (!seen.add(instruction.agent())) {
                    violations.add("agent " + instruction.agent() + " ran twice in phase " + phase);
                }
            } else {
                seen.clear();
                phase++;
            }
        }
        return violations;
    }

    /** The trips recorded, in order. */
    public synchronized List<TraceEvent.BarrierTripped> trips() {
        List<TraceEvent.BarrierTripped> trips = new ArrayList<>();
        entries.stream().filter(TraceEvent.BarrierTripped.class::isInstance)
                .forEach(entry -> trips.add((TraceEvent.BarrierTripped) entry));
        return trips;
    }
}
