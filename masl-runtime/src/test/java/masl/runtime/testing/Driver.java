package masl.runtime.testing;

import masl.runtime.PoolScheduler;
import masl.runtime.Scheduler;
import masl.runtime.ThreadPerAgentScheduler;

/** The ways of running the same program objects that every concurrency test is run with. */
public enum Driver {
    /** Tasks on a pool of one worker per core. */
    POOL {
        @Override
        public Scheduler newScheduler() {
            return new PoolScheduler();
        }
    },
    /** Tasks on a single worker: any agent that held its thread while waiting would hang the mission. */
    SINGLE_WORKER {
        @Override
        public Scheduler newScheduler() {
            return new PoolScheduler(1);
        }
    },
    /** One platform thread per agent. */
    THREADS {
        @Override
        public Scheduler newScheduler() {
            return new ThreadPerAgentScheduler();
        }
    };

    public abstract Scheduler newScheduler();
}
