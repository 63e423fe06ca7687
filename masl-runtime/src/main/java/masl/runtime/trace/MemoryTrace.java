package masl.runtime.trace;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;

/** A trace kept in memory, for tests. */
public final class MemoryTrace implements Trace {

    private final List<TraceEvent> events = new ArrayList<>();

    @Override
    public synchronized void record(TraceEvent event) {
        events.add(event);
    }

    /** A copy of every event recorded so far, in order. */
    public synchronized List<TraceEvent> events() {
        return new ArrayList<>(events);
    }

    /** The events of one kind, in order. */
    public <E extends TraceEvent> List<E> events(Class<E> kind) {
        return events().stream().filter(kind::isInstance).map(kind::cast).collect(Collectors.toList());
    }
}
