package masl.runtime.event;

import masl.runtime.Agent;
import masl.runtime.Event;
import masl.runtime.entry.Entry;
import masl.runtime.entry.Membership;
import masl.runtime.trace.TraceEvent;

/**
 * An agent's emitting side (MASL §8): {@code emit} of its block's events, to itself (a local event)
 * or to every member of the block (a shared one), and the system events it raises for itself.
 * Traces each emission; the receivers perceive it through their agents.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public final class Emitter {

    /** What an emitter needs of its agent beyond the agent's public side. */
    public interface Site {

        /** The current runtime call is made from the case the program counter names. */
        void atCurrentCase();

        /** The mission clock, for trace timestamps. */
        long now();

        void record(TraceEvent event);

        /** Makes {@code receiver} perceive {@code occurrence}: from any thread, never blocks. */
        void deliver(Agent receiver, EventOccurrence occurrence);
    }

    private final Agent agent;
    private final Site site;

    public Emitter(Agent agent, Site site) {
        this.agent = agent;
        this.site = site;
    }

    /** {@code emit(event, message)} by the agent's program: a system event is raised, others go to their receivers. */
    public void emit(Event event, String message) {
        site.atCurrentCase();
        if (event.isSystemEvent()) {
            raise(event, message);
            return;
        }
        Entry block = agent.entry(event.block());
        requireMember(event, block);
        Agent[] receivers = event.isShared() ? block.perceivers() : new Agent[] {agent};
        EventOccurrence occurrence = new EventOccurrence(event, message, agent.id());
        site.record(new TraceEvent.EventEmitted(site.now(), agent.id(), event.name(), block.name(), message,
                receivers.length, agent.source()));
        for (Agent receiver : receivers) {
            site.deliver(receiver, occurrence);
        }
    }

    /**
     * Makes the agent perceive a system event ({@code timeout}, {@code uncaught_exception},
     * {@code forbidden_access}: local to it, §8). Safe from any thread, for instance from an agent
     * serving an invocation that this agent made.
     */
    public void raise(Event systemEvent, String message) {
        if (!systemEvent.isSystemEvent()) {
            throw new IllegalArgumentException(systemEvent + " is not a system event");
        }
        site.record(new TraceEvent.EventEmitted(site.now(), agent.id(), systemEvent.name(), null, message, 1,
                agent.source()));
        site.deliver(agent, new EventOccurrence(systemEvent, message, agent.id()));
    }

    private void requireMember(Event event, Entry block) {
        for (Membership membership : agent.memberships) {
            if (membership.entry == block) {
                return;
            }
        }
        throw new IllegalStateException(agent.describe() + " emits " + event + " outside that block");
    }
}
