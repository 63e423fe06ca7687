package masl.runtime;

import java.util.List;

/**
 * A translated MASL program, as the translator generates it (one mission class per program): the
 * agents it declares and how to add them, with their programs and the top-level block, to a
 * {@link Mission.Builder}. Launchers (the command line, the simulator, the JADE bridge, tests)
 * choose the scheduler, journal and trace, and may supply the agents' implementations themselves
 * (a simulated robot is an implementation bound to a body).
 */
public interface MissionProgram {

    /** An agent the program declares: its MASL name and the full class name of its type. */
    record AgentSpec(String name, String typeClassName) {
    }

    /** The agents of the program's declarations, in declaration order (proxy id order). */
    List<AgentSpec> agents();

    /**
     * Declares every agent on {@code builder}, in {@link #agents()} order, with the implementation
     * {@code implementations} gives for it and its program, and sets the top-level block.
     */
    Mission.Builder configure(Mission.Builder builder, ImplementationFactory implementations);

    /** Gives each agent its implementation: an instance of its type's class or of a subclass. */
    @FunctionalInterface
    interface ImplementationFactory {
        AgentImplementation create(AgentSpec agent) throws ReflectiveOperationException;
    }
}
