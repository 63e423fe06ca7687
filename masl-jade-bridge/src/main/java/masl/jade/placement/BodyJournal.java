package masl.jade.placement;

import java.util.function.Function;
import masl.runtime.AgentServices;

/**
 * The services of a body placed in a container away from the coordinator: its proxy id, and a
 * journal that collects what a primitive writes while it serves the coordinator's request, so that
 * the answer carries it to the mission's journal. Text written by a thread serving no request (a
 * thread a primitive started) goes with the next answer.
 */
final class BodyJournal implements AgentServices {

    private final int proxyId;
    private final ThreadLocal<StringBuilder> serving = new ThreadLocal<>();
    private final StringBuilder unclaimed = new StringBuilder();

    BodyJournal(int proxyId) {
        this.proxyId = proxyId;
    }

    @Override
    public int proxyId() {
        return proxyId;
    }

    @Override
    public void log(String text) {
        StringBuilder written = serving.get();
        if (written != null) {
            written.append(text);
        } else {
            synchronized (unclaimed) {
                unclaimed.append(text);
            }
        }
    }

    /** Really blocks the thread serving the primitive, as in-process. */
    @Override
    public void sleep(long ms) throws InterruptedException {
        Thread.sleep(Math.max(0, ms));
    }

    /** Runs {@code work} with what the calling thread logs meanwhile collected in the builder it gets. */
    <T> T collecting(Function<StringBuilder, T> work) {
        StringBuilder written = new StringBuilder();
        synchronized (unclaimed) {
            written.append(unclaimed);
            unclaimed.setLength(0);
        }
        serving.set(written);
        try {
            return work.apply(written);
        } finally {
            serving.remove();
        }
    }
}
