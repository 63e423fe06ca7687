package masl.jade;

import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import masl.jade.acl.Argument;
import masl.jade.acl.ContentException;
import masl.jade.acl.InvocationRequest;
import masl.jade.acl.JsonValues;
import masl.jade.platform.JadeException;
import masl.runtime.AgentImplementation;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.Primitive;

/**
 * The primitives of an agent type that a request may invoke: those its descriptor declares (own and
 * inherited), each bound to the public method of the implementation class that implements it. A
 * request naming anything else, or giving arguments the method cannot take, is not understood.
 * Immutable.
 *
 * <p>Public for {@code placement}, {@code outside} and {@code external}, which bind requests and make
 * stubs through it, and for {@code deployment}, which runs the calls of agents in other JVMs by name.
 */
public final class PrimitiveTable {

    private final AgentType type;
    private final Map<String, Binding> primitives = new LinkedHashMap<>();

    private record Binding(Primitive primitive, Method method) {
    }

    /** A request bound to its method, with its arguments converted: ready to run. */
    public record Call(Primitive primitive, Method method, Object[] args) {

        /**
         * Runs the primitive on {@code target} (ignored for a static one).
         *
         * @throws InvocationTargetException wrapping what the primitive threw
         */
        public Object invoke(AgentImplementation target) throws InvocationTargetException {
            try {
                return method.invoke(Modifier.isStatic(method.getModifiers()) ? null : target, args);
            } catch (IllegalAccessException e) {
                throw new IllegalStateException(method + " is not public", e);
            }
        }
    }

    /**
     * @throws JadeException if a primitive the descriptor declares has no public method of that name
     *                       and number of parameters in {@code implementation}
     */
    public PrimitiveTable(AgentType type, Class<? extends AgentImplementation> implementation) {
        this.type = type;
        for (Primitive primitive : type.primitives()) {
            Method method = Arrays.stream(implementation.getMethods())
                    .filter(candidate -> candidate.getName().equals(primitive.name())
                            && candidate.getParameterCount() == primitive.parameters().size())
                    .findFirst()
                    .orElseThrow(() -> new JadeException(implementation.getName() + " has no public method "
                            + primitive.signature() + " that " + type.shortName() + " declares"));
            primitives.put(primitive.name(), new Binding(primitive, method));
        }
    }

    public AgentType type() {
        return type;
    }

    public List<Primitive> primitives() {
        return primitives.values().stream().map(Binding::primitive).toList();
    }

    /** The methods bound to the primitives, in the order of {@link #primitives()}. */
    public List<Method> methods() {
        return primitives.values().stream().map(Binding::method).toList();
    }

    /**
     * Binds a call whose arguments are already values of the parameters' types (a deployed agent's
     * call of an agent of this JVM, named in a mission's message).
     *
     * @throws IllegalArgumentException if the type has no such primitive, or not of that many arguments
     */
    public Call bind(String primitive, List<Object> args) {
        Binding binding = primitives.get(primitive);
        if (binding == null || binding.method().getParameterCount() != args.size()) {
            throw new IllegalArgumentException(type.shortName() + " has no primitive " + primitive + " of "
                    + args.size() + " arguments");
        }
        return new Call(binding.primitive(), binding.method(), args.toArray());
    }

    /**
     * Binds a request: finds its primitive, checks the number of arguments and converts each to
     * its parameter's type.
     *
     * @throws ContentException positioned at the primitive's name or the faulty argument
     */
    public Call bind(InvocationRequest request) throws ContentException {
        Binding binding = primitives.get(request.primitive());
        if (binding == null) {
            throw new ContentException("unknown primitive \"" + request.primitive() + "\": " + type.shortName()
                    + " has " + String.join(", ", primitives.keySet()), request.line(), request.column());
        }
        Class<?>[] types = binding.method().getParameterTypes();
        List<Argument> args = request.args();
        if (args.size() != types.length) {
            throw new ContentException(binding.primitive().signature() + " takes " + types.length + " argument"
                    + (types.length == 1 ? "" : "s") + ", got " + args.size(), request.line(), request.column());
        }
        Object[] values = new Object[types.length];
        for (int i = 0; i < types.length; i++) {
            values[i] = JsonValues.fromJson(args.get(i), types[i], "argument " + (i + 1) + " of "
                    + binding.primitive().name());
        }
        return new Call(binding.primitive(), binding.method(), values);
    }
}
