package masl.testing;

import masl.runtime.scheduling.PoolScheduler;
import masl.runtime.scheduling.Scheduler;
import masl.runtime.scheduling.SeededScheduler;
import masl.runtime.scheduling.ThreadPerAgentScheduler;

/**
 * Who runs a mission's agents: the real pool, one thread per agent, or one thread drawing every
 * choice from a seed on a virtual clock (reproducible). Its text says how to replay a run.
 */
public sealed interface Schedule {

    Scheduler newScheduler();

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
            return "the pool scheduler";
        }
    }

    record Threads() implements Schedule {
        @Override
        public Scheduler newScheduler() {
            return new ThreadPerAgentScheduler();
        }

        @Override
        public String toString() {
            return "one thread per agent";
        }
    }

    record Seeded(long seed) implements Schedule {
        @Override
        public Scheduler newScheduler() {
            return new SeededScheduler(seed);
        }

        @Override
        public String toString() {
            return "seed " + seed + " (replay: runWith(Schedule.seed(" + seed + "L)), or masl run --seed " + seed + ")";
        }
    }
}
