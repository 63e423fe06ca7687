package masl.runtime.scheduling;

import static org.openjdk.jcstress.annotations.Expect.ACCEPTABLE;
import static org.openjdk.jcstress.annotations.Expect.FORBIDDEN;

import org.openjdk.jcstress.annotations.Actor;
import org.openjdk.jcstress.annotations.Description;
import org.openjdk.jcstress.annotations.JCStressTest;
import org.openjdk.jcstress.annotations.Outcome;
import org.openjdk.jcstress.annotations.State;
import org.openjdk.jcstress.infra.results.ZZ_Result;

/**
 * Two wake-ups of one parked agent's ticket (a barrier's trip and a death that trips it, a future
 * completing and a time limit): the first to come wins and schedules the agent, the other does
 * nothing.
 */
@JCStressTest
@Description("Two unparks of one ticket schedule a parked agent exactly once")
@Outcome(id = {"true, false", "false, true"}, expect = ACCEPTABLE, desc = "one waker schedules it")
@Outcome(expect = FORBIDDEN, desc = "scheduled twice or never")
@State
public class RunStateTwoWakeUps {

    private final RunState run = new LoneRunState();
    private final long ticket;

    public RunStateTwoWakeUps() {
        run.startSlice();
        ticket = run.issueTicket();
        run.park(false);
    }

    @Actor
    public void first(ZZ_Result r) {
        r.r1 = run.endPark(ticket);
    }

    @Actor
    public void second(ZZ_Result r) {
        r.r2 = run.endPark(ticket);
    }
}
