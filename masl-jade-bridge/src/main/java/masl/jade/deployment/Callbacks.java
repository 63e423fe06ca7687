package masl.jade.deployment;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;
import java.util.function.Function;
import masl.runtime.RemotePrimitiveException;

/**
 * The Java code a deployed agent's program hands its context (a primitive's call, an attribute's read,
 * a shared variable's update), kept in the container under a number: the mission decides whether and
 * when it runs (permeability, the callee's turn, the variable's lock) and asks the container to run it
 * by that number. A call's result stays here, for the program that made it; only an update's value
 * travels, to the mission that owns the variable.
 */
final class Callbacks {

    private record Pending(Function<JsonNode, Object> work, boolean valueTravels) {
    }

    private final AtomicLong numbers = new AtomicLong();
    private final Map<Long, Pending> pending = new ConcurrentHashMap<>();
    private final Map<Long, Object> results = new ConcurrentHashMap<>();

    /** A call whose result stays here ({@link #result}). */
    long call(Callable<?> call) {
        return add(new Pending(ignored -> {
            try {
                return call.call();
            } catch (RuntimeException | Error unchecked) {
                throw unchecked;
            } catch (Exception checked) {
                throw new CheckedFailure(checked);
            }
        }, false));
    }

    /** A function of a shared variable's value, whose result travels: both as {@link Values} writes them. */
    long function(Function<JsonNode, JsonNode> function) {
        return add(new Pending(function::apply, true));
    }

    /**
     * A label's store ({@code l.x = a.m()}, §10), run when the mission's label counts the call, with the
     * value {@code result} makes of the mission's argument (how the call ended, as {@link StandIn#ended}
     * says it).
     */
    long store(Function<JsonNode, Object> result, Consumer<Object> store) {
        return add(new Pending(ended -> {
            store.accept(result.apply(ended));
            return null;
        }, false));
    }

    /** The number of a call whose code stays with the program that made it: one that names its primitive. */
    long number() {
        return numbers.incrementAndGet();
    }

    private long add(Pending work) {
        long number = number();
        pending.put(number, work);
        return number;
    }

    /**
     * Runs callback {@code number} for the mission's {@code run} request and makes the answer: {@code
     * ran} (with the value if it travels) or {@code threw}, with the exception's class name and message.
     */
    ObjectNode run(long number, JsonNode argument) {
        ObjectNode answer = JsonNodeFactory.instance.objectNode();
        Pending work = pending.remove(number);
        if (work == null) {
            return answer.put("outcome", "threw").put("class", IllegalStateException.class.getName())
                    .put("message", "no call " + number + " waits here");
        }
        try {
            Object result = work.work().apply(argument);
            if (work.valueTravels()) {
                answer.set("value", (JsonNode) result);
            } else if (result != null) {
                results.put(number, result);
            }
            return answer.put("outcome", "ran");
        } catch (CheckedFailure failure) {
            return threw(answer, failure.getCause());
        } catch (RuntimeException | Error failure) {
            return threw(answer, failure);
        }
    }

    /** The answer saying a run threw {@code failure}: its class's name and message. */
    static ObjectNode threw(ObjectNode answer, Throwable failure) {
        return answer.put("outcome", "threw").put("class", RemotePrimitiveException.classNameOf(failure))
                .put("message", String.valueOf(failure.getMessage()));
    }

    /**
     * The result of call {@code number}, still kept: a label's store reads it before the program's future
     * of the call completes, which the mission holds back until the store has run.
     */
    Object kept(long number) {
        return results.get(number);
    }

    /** The result of call {@code number} if the mission says it ran, else {@code defaultValue}; forgets it. */
    Object result(long number, boolean ran, Object defaultValue) {
        pending.remove(number);
        Object result = results.remove(number);
        return ran ? result : defaultValue;
    }

    /** A checked exception a call threw, carried through a {@link Function}. */
    private static final class CheckedFailure extends RuntimeException {
        private static final long serialVersionUID = 1L;

        CheckedFailure(Exception cause) {
            super(cause);
        }
    }
}
