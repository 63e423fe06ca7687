package masl.runtime;

import masl.runtime.scheduling.Blocking;
import masl.runtime.scheduling.ClockedCall;

/** What an agent's implementation reaches its mission through: its proxy id, the journal, sleeping. */
final class MissionServices implements AgentServices {
    private final int id;
    private final Journal journal;

    MissionServices(int id, Journal journal) {
        this.id = id;
        this.journal = journal;
    }

    @Override
    public int proxyId() {
        return id;
    }

    @Override
    public void log(String text) {
        journal.append(text);
    }

    /**
     * On a mission clock, sleeps in mission time ({@link ClockedCall}); otherwise really blocks
     * the calling thread (a primitive's Java code), the pool staying live meanwhile.
     */
    @Override
    public void sleep(long ms) throws InterruptedException {
        if (!ClockedCall.sleep(ms)) {
            Blocking.sleep(ms);
        }
    }
}
