package masl.jade.deployment;

import java.lang.reflect.Field;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.util.List;
import masl.jade.PrimitiveTable;
import masl.jade.stub.StubClasses;
import masl.runtime.AgentImplementation;
import masl.runtime.RemotePrimitiveException;
import masl.runtime.descriptor.AgentType;

/**
 * The members of one agent that a message may name: the primitives and attributes its type declares,
 * bound to its implementation class. An invocation or attribute access that reaches an agent by name
 * (from a deployed agent in another JVM) runs through it on the agent's object in this JVM: nothing
 * else of the class can be named, so a message runs only what the program could.
 */
final class Members {

    /**
     * The stubs of agents that run elsewhere, in the coordinator and in containers: one class per
     * implementation class in this JVM, whichever mission it is made for (javac is slow to start).
     */
    static final StubClasses STUBS = new StubClasses();

    private final AgentType type;
    private final PrimitiveTable primitives;
    private final Class<? extends AgentImplementation> implementation;

    Members(AgentType type, Class<? extends AgentImplementation> implementation) {
        this.type = type;
        this.primitives = new PrimitiveTable(type, implementation);
        this.implementation = implementation;
    }

    /** The methods of the type's primitives, in the order a stub of the class forwards them. */
    List<Method> methods() {
        return primitives.methods();
    }

    /** Whether {@code primitive} is one of the type's. */
    boolean declares(String primitive) {
        return type.findPrimitive(primitive).isPresent();
    }

    /**
     * Runs {@code primitive} with {@code args} on {@code target} and returns its result; throws what
     * the primitive threw ({@link RemotePrimitiveException} for a checked exception, named after it).
     *
     * @throws IllegalArgumentException if the type has no such primitive, or not with those arguments
     */
    Object invoke(AgentImplementation target, String primitive, List<Object> args) {
        try {
            return primitives.bind(primitive, args).invoke(target);
        } catch (InvocationTargetException thrown) {
            Throwable cause = thrown.getCause();
            if (cause instanceof RuntimeException unchecked) {
                throw unchecked;
            }
            if (cause instanceof Error error) {
                throw error;
            }
            throw new RemotePrimitiveException(cause.getClass().getName(), String.valueOf(cause.getMessage()));
        }
    }

    /** The value of attribute {@code attribute} of {@code target}. */
    Object read(AgentImplementation target, String attribute) {
        try {
            return field(attribute).get(target);
        } catch (IllegalAccessException notPublic) {
            throw new IllegalStateException(attribute + " of " + type.shortName() + " is not public", notPublic);
        }
    }

    /** Sets attribute {@code attribute} of {@code target} to {@code value}. */
    void write(AgentImplementation target, String attribute, Object value) {
        try {
            field(attribute).set(target, value);
        } catch (IllegalAccessException notPublic) {
            throw new IllegalStateException(attribute + " of " + type.shortName() + " is not public", notPublic);
        }
    }

    /**
     * The value {@code write}, a program's write of {@code attribute} of {@code owner} ({@code () ->
     * owner.x = v}), writes: run on {@code owner}, a stub whose field is then put back as it was.
     */
    Object written(AgentImplementation owner, String attribute, Runnable write) {
        synchronized (owner) {
            Object before = read(owner, attribute);
            try {
                write.run();
                return read(owner, attribute);
            } finally {
                write(owner, attribute, before);
            }
        }
    }

    /** @throws IllegalArgumentException if the type declares no such attribute, or the class has no public field for it */
    private Field field(String attribute) {
        if (type.findAttribute(attribute).isEmpty()) {
            throw new IllegalArgumentException(type.shortName() + " has no attribute " + attribute);
        }
        try {
            return implementation.getField(attribute);
        } catch (NoSuchFieldException missing) {
            throw new IllegalArgumentException(implementation.getName() + " has no public field " + attribute
                    + " for the attribute " + type.shortName() + " declares");
        }
    }
}
