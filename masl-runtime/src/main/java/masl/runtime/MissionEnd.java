package masl.runtime;

import java.util.List;
import java.util.Locale;
import java.util.function.LongSupplier;
import masl.runtime.entry.EntryCoordinator;
import masl.runtime.trace.Trace;
import masl.runtime.trace.TraceEvent;

/**
 * The end of a mission, written once it is decided: the {@code mission-ended} record, then, unless
 * the mission completed, the report of where each agent was. A timeout or a signal may end a mission
 * whose data fills the heap: if writing the end finds no room, the reserve ({@link MemoryReserve})
 * is released and the end written in its room, the record still once.
 */
final class MissionEnd {

    private final List<Agent> agents;
    private final EntryCoordinator coordinator;
    private final Trace trace;
    private final LongSupplier clock;
    private boolean recorded;

    MissionEnd(List<Agent> agents, EntryCoordinator coordinator, Trace trace, LongSupplier clock) {
        this.agents = agents;
        this.coordinator = coordinator;
        this.trace = trace;
        this.clock = clock;
    }

    /** Records the end and returns the report ({@code ""} for a completed mission); {@code stopReason} may be null. */
    String write(MissionOutcome.Status status, String stopReason) {
        try {
            return writeOnce(status, stopReason);
        } catch (OutOfMemoryError noRoom) {
            MemoryReserve.exhausted();
            return writeOnce(status, stopReason);
        }
    }

    private String writeOnce(MissionOutcome.Status status, String stopReason) {
        if (!recorded) {
            trace.record(new TraceEvent.MissionEnded(clock.getAsLong(), status.name().toLowerCase(Locale.ROOT),
                    status == MissionOutcome.Status.STOPPED ? stopReason : null));
            recorded = true;
        }
        return status == MissionOutcome.Status.COMPLETED ? "" : report();
    }

    /** One line per agent: its program counter and chain of blocks. */
    private String report() {
        return coordinator.query(() -> {
            StringBuilder report = new StringBuilder();
            for (Agent agent : agents) {
                report.append(agent.describe()).append(": ").append(agent.memberships.isEmpty()
                        ? "in no block" : agent.memberships.toString()).append('\n');
            }
            return report.toString();
        });
    }
}
