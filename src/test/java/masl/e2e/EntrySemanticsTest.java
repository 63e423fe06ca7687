package masl.e2e;

import java.util.stream.LongStream;
import masl.testing.MaslMission;
import masl.testing.Schedule;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * The entry-block rules of MASL §4 and §6.4 that programs written in the language designer's style
 * rely on, from MASL source, over seeds, the pool and a thread per agent: the top-level block has
 * one wave; each asynchronous or scalar child of a synchronous block is one instruction, also in
 * an e-sequence; an agent held by a child's entry barrier is still active in its ancestors.
 */
@Tag("slow")
class EntrySemanticsTest {

    private static final int SEEDS = 500;
    private static final int POOL_RUNS = 50;
    private static final int THREAD_RUNS = 50;
    private static final int LATE_MS = 20;

    /** §4: every agent tests main first, and all that pass form its one wave, however late one is. */
    @Test
    void anAsynchronousMainHasOneWaveWhoseSharedCounterEndsAtTheTeamsSize() {
        assertEveryScheduleGivesWithALateAgent("one_wave.masl", """
                import Default.xml as Default;
                Default a0, a1, a2, a3 = newAgent(Default);
                asynchronous entry main (masl.e2e.Slow.pause(.getProxyID() == 3, PAUSE)) {
                    shared int n = 0;
                    scalar entry greet (true) {
                        .logln("hello");
                    }
                    n++;
                    synchronous entry report (true) {
                        scalar entry say (true) {
                            .logln("n=" + n);
                        }
                    }
                }
                """, "hello\nn=4\n");
    }

    /** §4: a scalar main is run by a single agent, once per mission. */
    @Test
    void aScalarMainRunsOnce() {
        assertEveryScheduleGivesWithALateAgent("scalar_main.masl", """
                import Default.xml as Default;
                Default a0, a1, a2 = newAgent(Default);
                scalar entry main (masl.e2e.Slow.pause(.getProxyID() == 2, PAUSE)) {
                    .logln("once");
                }
                """, "once\n");
    }

    /**
     * §6.4: in a synchronous block, {@code print} and {@code dash} are each one instruction: nobody
     * starts {@code dash} (nor {@code done}) before {@code print} has finished, though they stand in
     * one e-sequence.
     */
    @Test
    void eachAsynchronousOrScalarChildOfASynchronousBlockIsOneInstructionInAnESequence() {
        MaslMission mission = MaslMission.fromString("print_dash.masl", """
                import Default.xml as Default;
                Default a0, a1, a2 = newAgent(Default);
                synchronous entry main (true) {
                    scalar entry print (true) {
                        .sleep(20);
                        .logln("printed");
                    }
                    asynchronous entry dash (.getProxyID() == 2) {
                        .logln("dash");
                    }
                    scalar entry done (true) {
                        .logln("done");
                    }
                }
                """);
        assertEveryScheduleGives(mission, "printed\ndash\ndone\n");
    }

    /**
     * §6.4, last paragraph: workers held by the locked entry barrier of {@code work} are still
     * active in {@code main}, so the supervisor keeps releasing pairs until every worker is through.
     */
    @Test
    void agentsHeldByAChildsEntryBarrierStayActiveInTheirAncestors() {
        MaslMission mission = MaslMission.fromString("supervisor.masl", """
                import Default.xml as Default;
                Default boss, w1, w2, w3, w4 = newAgent(Default);
                Entry work;
                asynchronous entry main (true) {
                    if (.getProxyID() == 0) {
                        work.lock();
                    }
                    asynchronous entry supervise (.getProxyID() == 0) {
                        while (main.getActiveCount() > 1) {
                            if (work.getWaitingInCount() >= 2 && work.getWaitingInCount() == work.count) {
                                .logln("pair");
                                work.release(2);
                            }
                        }
                        .logln("supervisor done");
                    }
                    synchronous entry work (.getProxyID() != 0) {
                        .logln("work " + .getProxyID());
                    }
                }
                """);
        mission.explore(LongStream.range(0, 300), 0).assertEveryRun(run -> {
            run.assertCompleted();
            run.assertLinesInAnyOrder("pair", "pair", "work 1", "work 2", "work 3", "work 4", "supervisor done");
            run.assertEveryBefore("work .*", "supervisor done");
        });
    }

    private static void assertEveryScheduleGives(MaslMission mission, String journal) {
        assertEveryScheduleGives(mission, mission, journal);
    }

    /**
     * {@code program}'s {@code PAUSE} is how long one agent sleeps before its test, so that it
     * comes last: {@value #LATE_MS} ms on the pool and on threads, where the others then pass theirs
     * first; none under a seed, whose scheduler orders the slices itself and explores the late
     * agent's turn among the others, so that a pause would only cost time ({@value #SEEDS} seeds of
     * {@value #LATE_MS} ms).
     */
    private static void assertEveryScheduleGivesWithALateAgent(String name, String program, String journal) {
        MaslMission seeded = MaslMission.fromString(name, program.replace("PAUSE", "0"));
        MaslMission real = MaslMission.fromString(name, program.replace("PAUSE", String.valueOf(LATE_MS)));
        assertEveryScheduleGives(seeded, real, journal);
    }

    private static void assertEveryScheduleGives(MaslMission seeded, MaslMission real, String journal) {
        seeded.explore(SEEDS).assertEveryRun(run -> run.assertJournal(journal));
        real.explore(LongStream.empty(), POOL_RUNS).assertEveryRun(run -> run.assertJournal(journal));
        for (int i = 0; i < THREAD_RUNS; i++) {
            real.runWith(Schedule.threads()).assertJournal(journal);
        }
    }
}
