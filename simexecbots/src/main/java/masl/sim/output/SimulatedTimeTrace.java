package masl.sim.output;

import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.RecordComponent;
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

    /**
     * A copy of {@code event} at time {@code t}. Every kind of trace event is a record whose first
     * component is {@code nanos}; the copy goes through the record's canonical constructor so that
     * kinds and components the runtime adds later are restamped too, not lost or failed on.
     */
    static TraceEvent restamped(TraceEvent event, long t) {
        RecordComponent[] components = event.getClass().getRecordComponents();
        Class<?>[] types = new Class<?>[components.length];
        Object[] values = new Object[components.length];
        try {
            for (int i = 0; i < components.length; i++) {
                types[i] = components[i].getType();
                values[i] = i == 0 ? Long.valueOf(t) : components[i].getAccessor().invoke(event);
            }
            Constructor<? extends TraceEvent> canonical = event.getClass().getDeclaredConstructor(types);
            return canonical.newInstance(values);
        } catch (NoSuchMethodException | InstantiationException | IllegalAccessException e) {
            throw new IllegalStateException("trace event " + event.getClass().getName() + " is not a record", e);
        } catch (InvocationTargetException e) {
            throw new IllegalStateException("trace event " + event + " cannot be restamped", e.getCause());
        }
    }
}
