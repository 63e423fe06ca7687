package masl.runtime.entry;

import static org.openjdk.jcstress.annotations.Expect.ACCEPTABLE;
import static org.openjdk.jcstress.annotations.Expect.FORBIDDEN;

import masl.runtime.Agent;
import masl.runtime.EntryDefinition;
import masl.runtime.Mode;
import org.openjdk.jcstress.annotations.Actor;
import org.openjdk.jcstress.annotations.Arbiter;
import org.openjdk.jcstress.annotations.Description;
import org.openjdk.jcstress.annotations.JCStressTest;
import org.openjdk.jcstress.annotations.Outcome;
import org.openjdk.jcstress.annotations.State;
import org.openjdk.jcstress.infra.results.IZ_Result;

/**
 * The last participant's arrival, without the lock, against an agent joining the domain under the
 * coordinator's lock. Whichever is counted first, the phase is not complete afterwards: a join
 * between a completing arrival's count and its trip counts as having come first, so the barrier
 * never trips with the joiner missing.
 */
@JCStressTest
@Description("A join racing the last arrival keeps the phase from tripping without the joiner")
@Outcome(id = "0, false", expect = ACCEPTABLE, desc = "arrival counted first; the join reopens the phase")
@Outcome(id = "-1, false", expect = ACCEPTABLE, desc = "join counted first; the arrival completes nothing")
@Outcome(expect = FORBIDDEN, desc = "the phase can trip with the joiner unarrived")
@State
public class BarrierArrivalOrJoin {

    private static final EntryDefinition MAIN = EntryDefinition.main("main", Mode.SYNCHRONOUS);

    private final Agent last;
    private final SynchronisationBarrier barrier;
    private final Object coordinatorLock = new Object();

    public BarrierArrivalOrJoin() {
        FinishingAgents built = new FinishingAgents(MAIN, 2);
        last = built.agents[1];
        barrier = built.mission.entry(MAIN).barrier;
        barrier.addParticipant();
        barrier.addParticipant();
        barrier.arrive(built.agents[0]);
    }

    @Actor
    public void lastArrival(IZ_Result r) {
        r.r1 = barrier.arrive(last);
    }

    @Actor
    public void join() {
        synchronized (coordinatorLock) {
            barrier.addParticipant();
        }
    }

    @Arbiter
    public void completes(IZ_Result r) {
        synchronized (coordinatorLock) {
            r.r2 = barrier.completes(0);
        }
    }
}
