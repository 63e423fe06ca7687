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
 * The end of a slice against the wake-up of its park: an agent whose slice issued a park ticket
 * ends the slice ({@link RunState#park}) while another thread ends the park
 * ({@link RunState#unpark}). Exactly one of them makes the agent runnable again: the waker when the
 * park came first, the slice ({@code park} fails, so it reschedules) when the wake-up did. Never
 * both (the agent would run on two threads), never neither (a lost wake-up: a hang).
 */
@JCStressTest
@Description("A park and the wake-up of its ticket reschedule the agent exactly once")
@Outcome(id = "true, true, false", expect = ACCEPTABLE, desc = "parked first; the waker schedules it")
@Outcome(id = "false, false, false", expect = ACCEPTABLE, desc = "woken while running; the slice reschedules it")
@Outcome(expect = FORBIDDEN, desc = "scheduled twice or never, or a ticket left pending")
@State
public class RunStateParkOrWakeUp {

    private final RunState run = new LoneRunState();
    private final long ticket;

    public RunStateParkOrWakeUp() {
        run.startSlice();
        ticket = run.issueTicket();
    }

    @Actor
    public void slice(ZZZ_Result r) {
        r.r1 = run.park(false);
    }

    @Actor
    public void waker(ZZZ_Result r) {
        r.r2 = run.endPark(ticket);
    }

    @Arbiter
    public void pending(ZZZ_Result r) {
        r.r3 = run.pendingTicket() != 0;
    }
}
