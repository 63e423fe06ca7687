package masl.testing;

import java.time.Duration;
import masl.runtime.Mission;
import masl.runtime.MissionOutcome;
import masl.runtime.scheduling.PoolScheduler;
import masl.runtime.scheduling.Scheduler;
import masl.runtime.scheduling.SeededScheduler;
import masl.runtime.scheduling.ThreadPerAgentScheduler;
import masl.runtime.trace.Trace;

/**
 * Who runs a mission's agents in this JVM: the real pool, one thread per agent, or one thread drawing
 * every choice from a seed on a virtual clock (reproducible).
 */
public sealed interface Schedule extends MissionPlatform {

    Scheduler newScheduler();

    /** A fresh in-process mission of the program, its agents run by this schedule's scheduler. */
    @Override
    default MissionOutcome run(TranslatedMission mission, Trace trace, Duration timeout) throws InterruptedException {
        Mission.Builder run = mission.loader().newMission()
                .scheduler(newScheduler())
                .journal(new StringBuilder())
                .trace(trace);
        mission.callTimeout().ifPresent(run::callTimeout);
        return run.build().run(timeout);
    }

    /** The pool of {@code masl run}: one worker per core. */
    static Schedule pool() {
        return new Pool();
    }

    /** One platform thread per agent, as {@code masl run --threads}. */
    static Schedule threads() {
        return new Threads();
    }

    /** The deterministic scheduler: the same seed gives the same journal and trace. */
    static Schedule seed(long seed) {
        return new Seeded(seed);
    }

    record Pool() implements Schedule {
        @Override
        public Scheduler newScheduler() {
            return new PoolScheduler();
        }

        @Override
        public String toString() {
            return "under the pool scheduler";
        }
    }

    record Threads() implements Schedule {
        @Override
        public Scheduler newScheduler() {
            return new ThreadPerAgentScheduler();
        }

        @Override
        public String toString() {
            return "under one thread per agent";
        }
    }

    record Seeded(long seed) implements Schedule {
        @Override
        public Scheduler newScheduler() {
            return new SeededScheduler(seed);
        }

        @Override
        public String toString() {
            return "under seed " + seed;
        }
    }
}
