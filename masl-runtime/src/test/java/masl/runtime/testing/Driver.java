package masl.runtime.testing;

import java.util.concurrent.atomic.AtomicLong;
import masl.runtime.scheduling.PoolScheduler;
import masl.runtime.scheduling.Scheduler;
import masl.runtime.scheduling.SeededScheduler;
import masl.runtime.scheduling.ThreadPerAgentScheduler;

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
    },
    /** One thread, a seeded random order and virtual time: each mission a new seed, so a new interleaving. */
    SEEDED {
        @Override
        public Scheduler newScheduler() {
            return new SeededScheduler(SEEDS.incrementAndGet());
        }
    };

    private static final AtomicLong SEEDS = new AtomicLong();

    public abstract Scheduler newScheduler();
}
