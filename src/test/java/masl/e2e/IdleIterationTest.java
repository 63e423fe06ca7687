package masl.e2e;

import masl.testing.MaslMission;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * MASL §5, "loop iterations", from MASL source, over seeds, the pool and a thread per agent: in a
 * synchronous block, an iteration of a loop in which the agent ran no instruction of non-zero
 * duration is one instruction, with the barrier; one that ran an instruction adds no step. So a
 * member busy-waiting in a synchronous block goes on in lock-step with the others instead of
 * holding them at the barrier they share. Each journal is written step by step ({@link StepJournal}).
 */
@Tag("slow")
class IdleIterationTest {

    private static final int SEEDS = 100;
    private static final int POOL_RUNS = 20;
    private static final int THREAD_RUNS = 20;

    /** Agent 0 logs at steps 1 and 6 of the block, agent 1 at each of steps 1 to 7. */
    private static final StepJournal ZERO_AT_STEPS_1_AND_6 = StepJournal.of("""
                0 step 1
                1 step 1

                1 step 2

                1 step 3

                1 step 4

                1 step 5

                0 step 6
                1 step 6

                1 step 7""");

    /** Agents 2 and 3 skip {@code write} and spin on its active count while 0 and 1 write in lock-step. */
    @Test
    void membersSpinningOnASynchronousChildLetItsMembersFinish() {
        assertEverySchedule("spinners.masl", """
                import Default.xml as Default;
                Default a, b, c, d = newAgent(Default);
                Entry write;
                synchronous entry main (true) {
                    synchronous entry dowork (true) {
                        synchronous entry write (.getProxyID() < 2) {
                            .logln(.getProxyID() + " writes");
                            .nop();
                            .logln(.getProxyID() + " wrote");
                        }
                        .logln(.getProxyID() + " after write");
                        while (write.getActiveCount() != 0) {}
                    }
                    .logln(.getProxyID() + " left dowork");
                }
                """, StepJournal.of("""
                0 writes
                1 writes
                2 after write
                3 after write

                0 wrote
                1 wrote

                0 after write
                1 after write

                0 left dowork
                1 left dowork
                2 left dowork
                3 left dowork"""));
    }

    /**
     * Two waves of {@code write}: the first let in by its free entry barrier; agent 1 leaves it by
     * {@code reelect} and waits at the barrier, locked since, until agent 0, the last of the first
     * wave, lets it in with {@code release()}: a second wave, while agents 2 and 3 spin on
     * {@code write}'s active count.
     */
    @Test
    void membersSpinningThroughTwoWavesOfASynchronousChildLetBothFinish() {
        assertEverySchedule("two_waves.masl", """
                import Default.xml as Default;
                Default a, b, c, d = newAgent(Default);
                Entry write;
                synchronous entry main (true) {
                    synchronous entry dowork (true) {
                        local int round = 0;
                        synchronous entry write (.getProxyID() < 2) {
                            round++;
                            .logln(.getProxyID() + " writes, round " + round);
                            if (.getProxyID() == 1 && round == 1) reelect;
                            .logln(.getProxyID() + " wrote, round " + round);
                        }
                        if (.getProxyID() == 0 && write.getWaitingInCount() > 0) write.release();
                        if (.getProxyID() >= 2) .logln(.getProxyID() + " skipped write");
                        while (write.getActiveCount() != 0) {}
                    }
                    .logln(.getProxyID() + " left dowork, write.count=" + write.count);
                }
                """, StepJournal.of("""
                2 skipped write
                3 skipped write

                0 writes, round 1
                1 writes, round 1

                0 wrote, round 1

                1 writes, round 2

                1 wrote, round 2

                0 left dowork, write.count=0
                1 left dowork, write.count=0
                2 left dowork, write.count=0
                3 left dowork, write.count=0"""));
    }

    /** Agent 1 spins on a shared variable that agent 0 sets after three instructions of the same block. */
    @Test
    void aMemberSpinningOnASharedVariableLetsTheOthersGoOnInLockStep() {
        assertEverySchedule("shared_flag.masl", """
                import Default.xml as Default;
                Default a, b = newAgent(Default);
                synchronous entry main (true) {
                    synchronous entry work (true) {
                        shared int done = 0;
                        if (.getProxyID() == 0) {
                            .logln("0 one");
                            .logln("0 two");
                            done = 1;
                        }
                        while (done == 0) {}
                    }
                    .logln(.getProxyID() + " left work");
                }
                """, StepJournal.of("""
                0 one

                0 two

                0 left work
                1 left work"""));
    }

    /**
     * Agent 0's four iterations are four steps: the two that run {@code nop()} are steps by it, the
     * two that run nothing are steps of their own; agent 1 logs a line every step meanwhile.
     */
    @Test
    void anIterationThatRanNoInstructionIsOneStepAndOneThatRanOneAddsNone() {
        assertEverySchedule("steps.masl", """
                import Default.xml as Default;
                Default a, b = newAgent(Default);
                synchronous entry main (true) {
                    local int k = 0;
                    .logln(.getProxyID() + " step 1");
                    if (.getProxyID() == 0) {
                        for (k = 0; k < 4; k++) {
                            if (k % 2 == 0) .nop();
                        }
                        .logln("0 step 6");
                    } else {
                        for (k = 2; k <= 7; k++) .logln("1 step " + k);
                    }
                }
                """, ZERO_AT_STEPS_1_AND_6);
    }

    /** Nested loops: each idle iteration of the inner loop is a step; the outer loop's iterations, which ran them, add none. */
    @Test
    void anIterationWhoseNestedLoopSteppedAddsNoStep() {
        assertEverySchedule("nested.masl", """
                import Default.xml as Default;
                Default a, b = newAgent(Default);
                synchronous entry main (true) {
                    local int i = 0;
                    local int j = 0;
                    .logln(.getProxyID() + " step 1");
                    if (.getProxyID() == 0) {
                        for (i = 0; i < 2; i++) {
                            for (j = 0; j < 2; j++) {}
                        }
                        .logln("0 step 6");
                    } else {
                        for (i = 2; i <= 7; i++) .logln("1 step " + i);
                    }
                }
                """, ZERO_AT_STEPS_1_AND_6);
    }

    private static void assertEverySchedule(String name, String program, StepJournal journal) {
        journal.assertEverySchedule(MaslMission.fromString(name, program), SEEDS, POOL_RUNS, THREAD_RUNS);
    }
}
