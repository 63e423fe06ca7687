package masl.runtime.entry;

import static org.openjdk.jcstress.annotations.Expect.ACCEPTABLE;
import static org.openjdk.jcstress.annotations.Expect.FORBIDDEN;

import java.util.ArrayList;
import java.util.List;
import masl.runtime.Agent;
import masl.runtime.EntryDefinition;
import masl.runtime.Mode;
import org.openjdk.jcstress.annotations.Actor;
import org.openjdk.jcstress.annotations.Arbiter;
import org.openjdk.jcstress.annotations.Description;
import org.openjdk.jcstress.annotations.JCStressTest;
import org.openjdk.jcstress.annotations.Outcome;
import org.openjdk.jcstress.annotations.State;
import org.openjdk.jcstress.infra.results.III_Result;

/**
 * Two participants arrive at once, without the lock ({@link SynchronisationBarrier#arrive}):
 * exactly one arrival completes phase 0, and its trip lets exactly the other agent go. An arrival
 * is pushed before it is counted, so the completing one always finds the other on the stack.
 */
@JCStressTest
@Description("Concurrent arrivals: one completes the phase, and the trip finds every other arrival")
@Outcome(id = {"0, -1, 1", "-1, 0, 1"}, expect = ACCEPTABLE, desc = "one completes; its trip lets the other go")
@Outcome(expect = FORBIDDEN, desc = "both or neither complete, or an arrival missing from the trip")
@State
public class BarrierLastArrival {

    private static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);

    private final Agent[] agents;
    private final SynchronisationBarrier barrier;

    public BarrierLastArrival() {
        FinishingAgents built = new FinishingAgents(MAIN, 2);
        agents = built.agents;
        barrier = built.mission.entry(MAIN).barrier;
        barrier.addParticipant();
        barrier.addParticipant();
    }

    @Actor
    public void first(III_Result r) {
        r.r1 = barrier.arrive(agents[0]);
    }

    @Actor
    public void second(III_Result r) {
        r.r2 = barrier.arrive(agents[1]);
    }

    @Arbiter
    public void trip(III_Result r) {
        Agent completing = r.r1 == 0 ? agents[0] : r.r2 == 0 ? agents[1] : null;
        if (completing == null || !barrier.completes(0)) {
            r.r3 = -1;
            return;
        }
        List<Agent> letGo = new ArrayList<>();
        barrier.trip(completing, letGo::add, chunk -> { });
        r.r3 = letGo.size() == 1 && letGo.get(0) != completing ? 1 : -1;
    }
}
