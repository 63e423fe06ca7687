package masl.runtime.trace;

/**
 * Receives every membership change, barrier trip and event emitted, reacted to or dropped of a
 * mission (components.md, "Runtime"). The runtime records membership changes under the lock that
 * orders the changes themselves, so a trace lists them in the order they happened; events are
 * recorded by the agents concerned without that lock (an emission before its delivery). An
 * implementation must therefore be thread-safe and quick, and must not call back into the mission.
 */
@FunctionalInterface
public interface Trace {

    /** A trace that drops everything: the default of a mission. */
    Trace NONE = event -> { };

    void record(TraceEvent event);
}
