package masl.e2e;

import masl.runtime.MissionOutcome;
import masl.testing.MaslMission;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * MASL §6.3, "Exit barrier", from MASL source, over seeds, the pool and a thread per agent: a member
 * of a synchronous block held by a descendant's entry or exit barrier still has an instruction of
 * the block to run, so it keeps the block's waiting-out members; the end of a child's wave and
 * the release of its parent's waiting-out members are never one step. Each journal is written step
 * by step ({@link StepJournal}), and {@code outer.count} says who was still a member.
 */
@Tag("slow")
class ExitBarrierTest {

    private static final int SEEDS = 100;
    private static final int POOL_RUNS = 20;
    private static final int THREAD_RUNS = 20;

    /** Agent 2 skips {@code kid} and waits out at {@code outer} while 0 and 1 are held by {@code kid}'s exit barrier. */
    @Test
    void membersHeldByAChildsExitBarrierKeepTheParentsWaitingOutMembers() {
        assertEverySchedule("kid.masl", """
                import Default.xml as Default;
                Default a, b, c = newAgent(Default);
                Entry outer;
                synchronous entry main (true) {
                    synchronous entry outer (true) {
                        synchronous entry kid (.getProxyID() != 2) { .nop(); }
                        .logln(.getProxyID() + " after kid, outer.count=" + outer.count);
                    }
                    .logln(.getProxyID() + " left outer");
                }
                """, StepJournal.of("""
                2 after kid, outer.count=3

                0 after kid, outer.count=3
                1 after kid, outer.count=3

                0 left outer
                1 left outer
                2 left outer"""));
    }

    /** Three levels: each block lets its waiting-out members go only once those inside its child are out and done. */
    @Test
    void everyAncestorWaitsForTheMembersOfItsDescendants() {
        assertEverySchedule("three_levels.masl", """
                import Default.xml as Default;
                Default a, b, c, d = newAgent(Default);
                Entry outer;
                Entry mid;
                synchronous entry main (true) {
                    synchronous entry outer (true) {
                        synchronous entry mid (.getProxyID() != 3) {
                            synchronous entry kid (.getProxyID() < 2) { .nop(); .nop(); }
                            .logln(.getProxyID() + " after kid, mid.count=" + mid.count);
                        }
                        .logln(.getProxyID() + " after mid, outer.count=" + outer.count);
                    }
                    .logln(.getProxyID() + " left outer");
                }
                """, StepJournal.of("""
                2 after kid, mid.count=3
                3 after mid, outer.count=4

                0 after kid, mid.count=3
                1 after kid, mid.count=3

                0 after mid, outer.count=4
                1 after mid, outer.count=4
                2 after mid, outer.count=4

                0 left outer
                1 left outer
                2 left outer
                3 left outer"""));
    }

    /**
     * An e-sequence of two synchronous children: the members of the short {@code left} and agent 4,
     * which skips both, wait out at {@code outer} for the members of {@code right}.
     */
    @Test
    void theMembersOfEveryChildOfAnESequenceKeepTheParentsWaitingOutMembers() {
        assertEverySchedule("two_children.masl", """
                import Default.xml as Default;
                Default a, b, c, d, e = newAgent(Default);
                Entry outer;
                synchronous entry main (true) {
                    synchronous entry outer (true) {
                        synchronous entry left (.getProxyID() < 2) { }
                        synchronous entry right (.getProxyID() == 2 || .getProxyID() == 3) { .nop(); .nop(); .nop(); }
                        .logln(.getProxyID() + " after the children, outer.count=" + outer.count);
                    }
                    .logln(.getProxyID() + " left outer");
                }
                """, StepJournal.of("""
                0 after the children, outer.count=5
                1 after the children, outer.count=5
                4 after the children, outer.count=5

                2 after the children, outer.count=5
                3 after the children, outer.count=5

                0 left outer
                1 left outer
                2 left outer
                3 left outer
                4 left outer"""));
    }

    /**
     * Agent 1 leaves {@code kid} by {@code reelect} and is held by its entry barrier, locked since
     * the first wave: it is still a member of {@code outer}, so agent 2 waits out there until agent
     * 0 has let it into {@code kid}'s second wave and it has finished it.
     */
    @Test
    void aMemberHeldByAChildsLockedEntryBarrierAfterReelectKeepsTheParentsWaitingOutMembers() {
        assertEverySchedule("reelect.masl", """
                import Default.xml as Default;
                Default a, b, c = newAgent(Default);
                Entry outer;
                Entry kid;
                synchronous entry main (true) {
                    local int rounds = 0;
                    synchronous entry outer (true) {
                        synchronous entry kid (.getProxyID() != 2) {
                            rounds++;
                            if (.getProxyID() == 1 && rounds == 1) reelect;
                            .nop();
                        }
                        if (.getProxyID() == 0 && kid.getWaitingInCount() > 0) kid.release();
                        .logln(.getProxyID() + " after kid, round " + rounds + ", outer.count=" + outer.count);
                    }
                    .logln(.getProxyID() + " left outer");
                }
                """, StepJournal.of("""
                2 after kid, round 0, outer.count=3

                0 after kid, round 1, outer.count=3

                1 after kid, round 2, outer.count=3

                0 left outer
                1 left outer
                2 left outer"""));
    }

    /** Agent 1 dies inside {@code kid}: it leaves every block, agent 0 goes on in {@code outer}, agent 2 waits for it. */
    @Test
    void aMemberThatDiesInTheChildEndsTheChildsWaveButNotTheParents() {
        assertEverySchedule("dying.masl", """
                import Default.xml as Default;
                Default a, b, c = newAgent(Default);
                Entry outer;
                synchronous entry main (true) {
                    local int zero = 0;
                    synchronous entry outer (true) {
                        synchronous entry kid (.getProxyID() != 2) {
                            .nop();
                            if (.getProxyID() == 1) zero = 1 / zero;
                            .nop();
                            .nop();
                        }
                        .logln(.getProxyID() + " after kid, outer.count=" + outer.count);
                    }
                    .logln(.getProxyID() + " left outer");
                }
                """, StepJournal.endingAs(MissionOutcome.Status.FAILED, """
                2 after kid, outer.count=3

                0 after kid, outer.count=2

                0 left outer
                2 left outer"""));
    }

    private static void assertEverySchedule(String name, String program, StepJournal journal) {
        journal.assertEverySchedule(MaslMission.fromString(name, program), SEEDS, POOL_RUNS, THREAD_RUNS);
    }
}
