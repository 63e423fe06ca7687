package masl.jade.deployment;

import java.lang.reflect.Array;
import java.lang.reflect.Method;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.Callable;
import masl.jade.stub.BodyStub;

/**
 * What an agent that runs elsewhere is in a container of deployed programs: a stub of its class
 * whose primitives, called inside a {@link #of recording}, note their name and arguments and run
 * nothing. The Java call a program hands its context for such an agent ({@code () -> b.count(2)})
 * is made at once, in a recording, so that only the primitive's name and its arguments' values go to
 * the mission, which has it run on the agent's real object, where that object is.
 */
final class Recording implements BodyStub {

    /** A primitive's call as the program made it. */
    record Call(String primitive, List<Object> args) {
    }

    private static final ThreadLocal<Call[]> CURRENT = new ThreadLocal<>();

    private final List<Method> methods;

    Recording(List<Method> methods) {
        this.methods = List.copyOf(methods);
    }

    /** The primitive {@code call} calls on a stub of this kind, with its arguments; null if it calls none. */
    static Call of(Callable<?> call) {
        Call[] made = new Call[1];
        CURRENT.set(made);
        try {
            call.call();
        } catch (Exception impossible) {
            // A recording stub's primitive throws nothing; the call's own code is the program's helper.
            throw new IllegalStateException("a recorded call threw " + impossible, impossible);
        } finally {
            CURRENT.remove();
        }
        return made[0];
    }

    @Override
    public Object call(int method, Object[] args) {
        Call[] recording = CURRENT.get();
        Method called = methods.get(method);
        if (recording == null) {
            throw new IllegalStateException(called.getName() + " runs where its agent runs, not in this container");
        }
        recording[0] = new Call(called.getName(), Arrays.asList(args));
        return zero(called.getReturnType());
    }

    /** The value a stub returns for a result it does not have: what unboxes to the primitive type's zero. */
    private static Object zero(Class<?> type) {
        return type.isPrimitive() && type != void.class ? Array.get(Array.newInstance(type, 1), 0) : null;
    }
}
