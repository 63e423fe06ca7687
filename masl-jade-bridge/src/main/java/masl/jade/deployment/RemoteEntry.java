package masl.jade.deployment;

import java.util.List;
import masl.runtime.Agent;
import masl.runtime.AgentImplementation;
import masl.runtime.EntryDefinition;
import masl.runtime.entry.Entry;

/**
 * A block's entry members ({@code e.count}, {@code e.release()}, §6.7) as a deployed agent's program
 * sees them: each a request to the mission, which owns the block's memberships and barriers.
 */
final class RemoteEntry extends Entry {

    private final EntryDefinition block;
    private final RemoteContext context;

    RemoteEntry(EntryDefinition block, RemoteContext context) {
        super(block, null, null);
        this.block = block;
        this.context = context;
    }

    @Override
    public int count() {
        return (int) context.entryCall(block, "count", 0);
    }

    @Override
    public List<AgentImplementation> getList() {
        return context.entryAgents(block, "getList");
    }

    @Override
    public int getActiveCount() {
        return (int) context.entryCall(block, "getActiveCount", 0);
    }

    @Override
    public List<AgentImplementation> getActiveList() {
        return context.entryAgents(block, "getActiveList");
    }

    @Override
    public int getWaitingInCount() {
        return (int) context.entryCall(block, "getWaitingInCount", 0);
    }

    @Override
    public List<AgentImplementation> getWaitingInList() {
        return context.entryAgents(block, "getWaitingInList");
    }

    @Override
    public int getWaitingOutCount() {
        return (int) context.entryCall(block, "getWaitingOutCount", 0);
    }

    @Override
    public List<AgentImplementation> getWaitingOutList() {
        return context.entryAgents(block, "getWaitingOutList");
    }

    @Override
    public String getLockPolicy() {
        return (String) context.entryCall(block, "getLockPolicy", 0);
    }

    @Override
    public void lock() {
        context.entryCall(block, "lock", 0);
    }

    @Override
    public void release() {
        context.entryCall(block, "release", Integer.MAX_VALUE);
    }

    @Override
    public void release(int n) {
        context.entryCall(block, "release", n);
    }

    /** The mission's agents, not this container's: a program never asks for them. */
    @Override
    public Agent[] perceivers() {
        throw new UnsupportedOperationException("the perceivers of " + block.name() + " are the mission's");
    }
}
