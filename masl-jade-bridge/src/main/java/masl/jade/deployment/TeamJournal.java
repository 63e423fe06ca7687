package masl.jade.deployment;

import masl.runtime.AgentServices;

/**
 * What the deployed agents' primitives write to the journal in their container: held until the
 * container's next message to the mission, which carries it, so that the mission appends it before
 * it acts on that message (before the barrier the writer arrives at, before the call it made returns),
 * and the journal keeps the one order it has in-process.
 */
final class TeamJournal {

    private final StringBuilder written = new StringBuilder();

    /** The services of agent {@code proxyId}'s implementation: its id, this journal, sleeping here. */
    AgentServices servicesOf(int proxyId) {
        return new AgentServices() {
            @Override
            public int proxyId() {
                return proxyId;
            }

            @Override
            public void log(String text) {
                synchronized (written) {
                    written.append(text);
                }
            }

            @Override
            public void sleep(long ms) throws InterruptedException {
                Thread.sleep(Math.max(0, ms));
            }
        };
    }

    /** Whether anything was written since the last {@link #drain}. */
    boolean written() {
        synchronized (written) {
            return written.length() > 0;
        }
    }

    /** What was written since the last call. */
    String drain() {
        synchronized (written) {
            String text = written.toString();
            written.setLength(0);
            return text;
        }
    }
}
