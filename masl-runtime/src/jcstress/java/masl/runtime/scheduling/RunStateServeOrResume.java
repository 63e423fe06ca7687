package masl.runtime.scheduling;

import static org.openjdk.jcstress.annotations.Expect.ACCEPTABLE;
import static org.openjdk.jcstress.annotations.Expect.FORBIDDEN;

import org.openjdk.jcstress.annotations.Actor;
import org.openjdk.jcstress.annotations.Arbiter;
import org.openjdk.jcstress.annotations.Description;
import org.openjdk.jcstress.annotations.JCStressTest;
import org.openjdk.jcstress.annotations.Outcome;
import org.openjdk.jcstress.annotations.State;
import org.openjdk.jcstress.infra.results.ZZZ_Result;

/**
 * An invocation queued for an agent parked at a barrier ({@link RunState#claimServing}) against a
 * pass that ends the park straight into the agent's slice ({@link RunState#resumeParked}), or, if
 * that fails, wakes it as any waker does ({@link RunState#unpark}). Whoever comes first owns the
 * agent: a claim first turns it {@code SERVING}, the pass neither runs nor schedules it, and the
 * serving slice schedules the program after; a pass first runs the slice, and the claim fails
 * (the slice serves the invocation at its next boundary). Never both, never neither.
 */
@JCStressTest
@Description("Serving a blocked agent and a pass resuming it: exactly one owner")
@Outcome(id = "true, false, true", expect = ACCEPTABLE, desc = "claimed first; the serving slice will schedule the program")
@Outcome(id = "false, true, false", expect = ACCEPTABLE, desc = "resumed first; the program's slice serves")
@Outcome(expect = FORBIDDEN, desc = "two owners, or none")
@State
public class RunStateServeOrResume {

    private final RunState run = new LoneRunState();
    private final long ticket;

    public RunStateServeOrResume() {
        run.startSlice();
        ticket = run.issueTicket();
        run.park(false);
    }

    @Actor
    public void invoker(ZZZ_Result r) {
        r.r1 = run.claimServing(() -> true);
    }

    @Actor
    public void pass(ZZZ_Result r) {
        r.r2 = run.resumeParked(ticket) || run.endPark(ticket);
    }

    @Arbiter
    public void serving(ZZZ_Result r) {
        r.r3 = run.isServing();
    }
}
