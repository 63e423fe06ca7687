package masl.sim.output;

import java.util.function.LongSupplier;
import masl.runtime.trace.Trace;
import masl.runtime.trace.TraceEvent;

/**
 * A runtime {@link Trace} whose events carry simulated time instead of {@link System#nanoTime()}:
 * each event's {@code nanos} is replaced by the simulated nanoseconds of the latest physics step
 * before it is passed on. In lock-step, a trace written through it is the same, byte for byte, for
 * the same seed.
 */
public final class SimulatedTimeTrace implements Trace {

    private final LongSupplier simulatedNanos;
    private final Trace next;

    /** @param simulatedNanos the simulated time now, in nanoseconds; @param next receives the restamped events */
    public SimulatedTimeTrace(LongSupplier simulatedNanos, Trace next) {
        this.simulatedNanos = simulatedNanos;
        this.next = next;
    }

    @Override
    public void record(TraceEvent event) {
        next.record(restamped(event, simulatedNanos.getAsLong()));
    }

    static TraceEvent restamped(TraceEvent event, long t) {
        if (event instanceof TraceEvent.Entered e) {
            return new TraceEvent.Entered(t, e.agent(), e.block(), e.source());
        } else if (event instanceof TraceEvent.WaitingIn e) {
            return new TraceEvent.WaitingIn(t, e.agent(), e.block(), e.source());
        } else if (event instanceof TraceEvent.Released e) {
            return new TraceEvent.Released(t, e.agent(), e.block(), e.wave(), e.source());
        } else if (event instanceof TraceEvent.WaitingOut e) {
            return new TraceEvent.WaitingOut(t, e.agent(), e.block(), e.source());
        } else if (event instanceof TraceEvent.Left e) {
            return new TraceEvent.Left(t, e.agent(), e.block(), e.cause(), e.source());
        } else if (event instanceof TraceEvent.BarrierTripped e) {
            return new TraceEvent.BarrierTripped(t, e.domain(), e.agents());
        } else if (event instanceof TraceEvent.WaveStarted e) {
            return new TraceEvent.WaveStarted(t, e.block(), e.wave());
        } else if (event instanceof TraceEvent.WaveEnded e) {
            return new TraceEvent.WaveEnded(t, e.block(), e.wave());
        } else if (event instanceof TraceEvent.MissionEnded e) {
            return new TraceEvent.MissionEnded(t, e.status());
        }
        return restampedAgentEvent(event, t);
    }

    private static TraceEvent restampedAgentEvent(TraceEvent event, long t) {
        if (event instanceof TraceEvent.EventEmitted e) {
            return new TraceEvent.EventEmitted(t, e.agent(), e.event(), e.block(), e.message(), e.receivers(), e.source());
        } else if (event instanceof TraceEvent.EventReacted e) {
            return new TraceEvent.EventReacted(t, e.agent(), e.event(), e.block(), e.byDefault(), e.source());
        } else if (event instanceof TraceEvent.EventDropped e) {
            return new TraceEvent.EventDropped(t, e.agent(), e.event(), e.source());
        } else if (event instanceof TraceEvent.InvocationMade e) {
            return new TraceEvent.InvocationMade(t, e.requester(), e.callee(), e.member(), e.source());
        } else if (event instanceof TraceEvent.InvocationServed e) {
            return new TraceEvent.InvocationServed(t, e.callee(), e.requester(), e.member(), e.source());
        } else if (event instanceof TraceEvent.InvocationDenied e) {
            return new TraceEvent.InvocationDenied(t, e.callee(), e.requester(), e.member(), e.state(), e.source());
        } else if (event instanceof TraceEvent.CountermeasureFired e) {
            return new TraceEvent.CountermeasureFired(t, e.agent(), e.callee(), e.member(), e.block(), e.source());
        }
        TraceEvent.AgentFailed e = (TraceEvent.AgentFailed) event;
        return new TraceEvent.AgentFailed(t, e.agent(), e.cause(), e.source());
    }
}
