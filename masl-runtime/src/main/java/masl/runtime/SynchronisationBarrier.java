package masl.runtime;

import java.util.ArrayList;
import java.util.List;

/**
 * The synchronisation barrier of one barrier domain (MASL §6.3, §6.4): an outermost synchronous
 * block and all its synchronous descendants reached through synchronous parents. Unlike a
 * {@link java.util.concurrent.Phaser} it never blocks a thread: an arriving agent is parked as data
 * and a trip makes the parked agents runnable.
 *
 * <p><b>Parties.</b> The participants are the agents with a membership of a block of the domain
 * that are held by no entry or exit barrier (anywhere in their chain). Membership is dynamic:
 * the {@link EntryCoordinator} adds and removes participants as agents join, are held, are
 * released and leave. <b>Trip:</b> when at least one participant has arrived and every participant
 * has, all arrived agents go on; a domain without participants never trips.
 *
 * <p>Guarded by the {@link EntryCoordinator}'s lock.
 */
final class SynchronisationBarrier {

    /** The outermost block of the domain, naming it in traces and reports. */
    final Entry domain;
    int participants;
    /** Participants parked at the barrier, in arrival order. */
    final List<Agent> arrived = new ArrayList<>();

    SynchronisationBarrier(Entry domain) {
        this.domain = domain;
    }

    /** Whether the participants not yet arrived are exactly {@code comingNow} more. */
    boolean completedBy(int comingNow) {
        int expected = arrived.size() + comingNow;
        if (expected > participants) {
            throw new IllegalStateException("barrier of " + domain.name() + ": " + expected
                    + " arrivals for " + participants + " participants");
        }
        return expected > 0 && expected == participants;
    }

    @Override
    public String toString() {
        return "barrier of " + domain.name() + " (" + arrived.size() + "/" + participants + ")";
    }
}
