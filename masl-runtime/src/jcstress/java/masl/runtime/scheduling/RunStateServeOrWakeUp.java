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
 * An invocation queued for a parked agent ({@link RunState#claimServing}) against the wake-up of
 * its park. Whoever comes first owns the agent: a claim first turns it {@code SERVING} and the
 * wake-up becomes {@code SERVING_WOKEN} (the serving slice schedules the program after), so the
 * waker schedules nothing; a wake-up first schedules the agent and the claim fails (the program's
 * slice serves the invocation at its next boundary). Never both, never neither.
 */
@JCStressTest
@Description("Serving a blocked agent and waking it: exactly one owner")
@Outcome(id = "true, false, true", expect = ACCEPTABLE, desc = "claimed first; the serving slice will schedule the program")
@Outcome(id = "false, true, false", expect = ACCEPTABLE, desc = "woken first; the program's slice serves")
@Outcome(expect = FORBIDDEN, desc = "two owners, or none")
@State
public class RunStateServeOrWakeUp {

    private final RunState run = new LoneRunState();
    private final long ticket;

    public RunStateServeOrWakeUp() {
        run.startSlice();
        ticket = run.issueTicket();
        run.park(false);
    }

    @Actor
    public void invoker(ZZZ_Result r) {
        r.r1 = run.claimServing(() -> true);
    }

    @Actor
    public void waker(ZZZ_Result r) {
        r.r2 = run.endPark(ticket);
    }

    @Arbiter
    public void serving(ZZZ_Result r) {
        r.r3 = run.isServing();
    }
}
