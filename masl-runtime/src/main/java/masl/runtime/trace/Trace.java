package masl.runtime.trace;

/**
 * Receives every membership change and barrier trip of a mission (components.md, "Runtime").
 * The runtime records under the lock that orders the changes themselves, so a trace lists them
 * in the order they happened; an implementation must therefore be quick and must not call back
 * into the mission.
 */
@FunctionalInterface
public interface Trace {

    /** A trace that drops everything: the default of a mission. */
    Trace NONE = event -> { };

    void record(TraceEvent event);
}
