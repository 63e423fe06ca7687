package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.Set;
import masl.runtime.trace.LeaveCause;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Test;

/** The stress test's checker finds what it is there to find. */
class MembershipCheckerTest {

    private final MembershipChecker checker = new MembershipChecker(Map.of("work", Set.of("work", "inner")));

    @Test
    void aTripOfEveryActiveMemberPassesAndHeldMembersAreNotCounted() {
        checker.record(new TraceEvent.WaitingIn(1, 0, "work", null));
        checker.record(new TraceEvent.WaitingIn(2, 1, "work", null));
        checker.record(new TraceEvent.Released(3, 0, "work", 1, null));
        checker.record(new TraceEvent.Released(4, 1, "work", 1, null));
        checker.record(new TraceEvent.BarrierTripped(5, "work", 2));
        checker.record(new TraceEvent.WaitingIn(6, 1, "inner", null));
        checker.record(new TraceEvent.BarrierTripped(7, "work", 1));
        checker.record(new TraceEvent.Left(8, 1, "inner", LeaveCause.FAILED, null));
        checker.record(new TraceEvent.Left(9, 1, "work", LeaveCause.FAILED, null));
        checker.record(new TraceEvent.Left(10, 0, "work", LeaveCause.BREAK, null));
        assertEquals(List.of(), checker.violations());
        assertEquals(Map.of(), checker.membersLeft());
        assertEquals(2, checker.trips("work"));
    }

    @Test
    void aTripMissingAMemberAndAMemberNeverLeavingAreFound() {
        checker.record(new TraceEvent.Entered(1, 0, "work", null));
        checker.record(new TraceEvent.Entered(2, 1, "work", null));
        checker.record(new TraceEvent.BarrierTripped(3, "work", 1));
        checker.record(new TraceEvent.Left(4, 0, "inner", LeaveCause.END, null));
        assertEquals(2, checker.violations().size(), checker.violations()::toString);
        assertTrue(checker.violations().get(0).contains("2 agents take part in work"), checker.violations()::toString);
        assertEquals(Set.of(0, 1), checker.membersLeft().keySet());
    }
}
