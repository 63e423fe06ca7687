package masl.runtime;

import java.lang.reflect.InvocationTargetException;

/**
 * Makes the implementation object of an agent from its class name, wherever the agent is created:
 * in the mission's JVM or in a container that hosts it. What the agent's own code threw is said in
 * words, since the reflective wrappers ({@code ExceptionInInitializerError},
 * {@code InvocationTargetException}) say nothing a user can act on.
 */
public final class AgentClasses {

    private AgentClasses() {
    }

    /**
     * A new instance of {@code className}, loaded and initialised by {@code classes}.
     *
     * @throws ReflectiveOperationException if the class is missing or has no usable constructor; a
     *     {@link CreationFailed} if its class cannot be linked, or its static initialiser or its
     *     constructor threw (it names what)
     * @throws ClassCastException if the class is not an {@link AgentImplementation}
     */
    public static AgentImplementation instantiate(String className, ClassLoader classes)
            throws ReflectiveOperationException {
        Class<?> type;
        try {
            type = Class.forName(className, true, classes);
        } catch (ExceptionInInitializerError thrown) {
            throw new CreationFailed("its static initialiser threw " + thrown.getCause());
        } catch (LinkageError broken) {
            throw new CreationFailed("its class cannot be loaded: " + broken);
        }
        try {
            return type.asSubclass(AgentImplementation.class).getDeclaredConstructor().newInstance();
        } catch (InvocationTargetException thrown) {
            throw new CreationFailed("its constructor threw " + thrown.getCause());
        }
    }

    /** An agent's implementation class was found but could not make an instance: the message says why. */
    public static final class CreationFailed extends ReflectiveOperationException {
        private static final long serialVersionUID = 1L;

        CreationFailed(String message) {
            super(message);
        }

        /** The message alone: it is printed after the agent's name and class. */
        @Override
        public String toString() {
            return getMessage();
        }
    }
}
