package masl.sim.output;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.lang.reflect.RecordComponent;
import java.util.ArrayList;
import java.util.List;
import masl.runtime.trace.TraceEvent;
import org.junit.jupiter.api.Test;

/** Every kind of runtime trace event is restamped with simulated time, its other components kept. */
class SimulatedTimeTraceTest {

    @Test
    void everyKindOfTraceEventGetsTheSimulatedTimeAndKeepsTheRest() throws Exception {
        for (Class<?> kind : TraceEvent.class.getPermittedSubclasses()) {
            TraceEvent event = sample(kind);
            List<TraceEvent> recorded = new ArrayList<>();
            new SimulatedTimeTrace(() -> 42L, recorded::add).record(event);

            TraceEvent restamped = recorded.get(0);
            assertEquals(kind, restamped.getClass());
            assertEquals(42L, restamped.nanos(), kind.getSimpleName());
            RecordComponent[] components = kind.getRecordComponents();
            for (int i = 1; i < components.length; i++) {
                assertEquals(components[i].getAccessor().invoke(event), components[i].getAccessor().invoke(restamped),
                        kind.getSimpleName() + "." + components[i].getName());
            }
        }
    }

    /** An event of {@code kind} with distinct values: nanos 7, numbers 3, strings, lists and enum constants named. */
    private static TraceEvent sample(Class<?> kind) throws Exception {
        RecordComponent[] components = kind.getRecordComponents();
        Class<?>[] types = new Class<?>[components.length];
        Object[] values = new Object[components.length];
        for (int i = 0; i < components.length; i++) {
            Class<?> type = components[i].getType();
            types[i] = type;
            if (type == long.class) {
                values[i] = 7L;
            } else if (type == int.class) {
                values[i] = 3;
            } else if (type == boolean.class) {
                values[i] = true;
            } else if (type == String.class) {
                values[i] = components[i].getName();
            } else if (type == List.class) {
                values[i] = List.of(components[i].getName());
            } else if (type.isEnum()) {
                values[i] = type.getEnumConstants()[0];
            } else {
                values[i] = null;
            }
        }
        return (TraceEvent) kind.getDeclaredConstructor(types).newInstance(values);
    }
}
