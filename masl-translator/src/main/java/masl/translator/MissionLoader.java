package masl.translator;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import masl.runtime.AgentClasses;
import masl.runtime.AgentImplementation;
import masl.runtime.Mission;
import masl.runtime.MissionProgram;
import masl.runtime.descriptor.AgentPath;
import masl.translator.compile.GeneratedCodeException;
import masl.translator.compile.InMemoryCompiler;

/**
 * Compiles a successful {@link Translation} in memory and makes missions of it: the generated
 * classes are loaded in a class loader over the agent path's folders and jars (users' agent types),
 * whose parent is the loader of masl itself (the runtime and the shipped agents, {@code masl.agents}).
 *
 * <pre>{@code
 * MissionLoader loaded = MissionLoader.load(translation, agentPath);
 * MissionOutcome outcome = loaded.newMission().journal(System.out).build().run(Duration.ofMinutes(1));
 * }</pre>
 */
public final class MissionLoader {

    private final ClassLoader classes;
    private final Class<? extends MissionProgram> missionClass;

    private MissionLoader(ClassLoader classes, Class<? extends MissionProgram> missionClass) {
        this.classes = classes;
        this.missionClass = missionClass;
    }

    /**
     * Compiles and loads {@code translation}.
     *
     * @throws IllegalArgumentException if the translation did not succeed
     * @throws GeneratedCodeException if javac rejects the generated code (a bug of masl), or the
     *     mission class cannot be loaded
     */
    public static MissionLoader load(Translation translation, AgentPath agentPath) {
        if (!translation.succeeded()) {
            throw new IllegalArgumentException("the translation of " + translation.source().name() + " has errors");
        }
        ClassLoader agents = agentPath.classLoader(MissionLoader.class.getClassLoader());
        List<String> classPath = new ArrayList<>();
        for (Path entry : agentPath.entries()) {
            classPath.add(entry.toString());
        }
        classPath.addAll(MaslClassPath.runtimeAndShippedAgents());
        List<InMemoryCompiler.Source> sources = new ArrayList<>();
        for (Map.Entry<String, String> source : translation.javaSources().entrySet()) {
            sources.add(new InMemoryCompiler.Source(source.getKey(), source.getValue()));
        }
        ClassLoader compiled;
        try {
            // javac recurses into nested constructs as the translator does.
            compiled = DeepStack.call("javac " + translation.source().name(),
                    () -> new InMemoryCompiler(classPath).compile(sources, agents));
        } catch (DeepStack.TooDeep overflow) {
            throw new GeneratedCodeException("javac overflowed the stack of " + DeepStack.STACK_BYTES
                    + " bytes on the generated code");
        }
        try {
            return new MissionLoader(compiled,
                    Class.forName(translation.missionClassName(), true, compiled).asSubclass(MissionProgram.class));
        } catch (ClassNotFoundException | ClassCastException | LinkageError e) {
            throw new GeneratedCodeException("cannot load the generated mission class " + translation.missionClassName()
                    + ": " + e);
        }
    }

    /** A new instance of the generated mission class. */
    public MissionProgram program() {
        try {
            return missionClass.getConstructor().newInstance();
        } catch (ReflectiveOperationException e) {
            throw new GeneratedCodeException("cannot instantiate " + missionClass.getName() + ": " + e);
        }
    }

    /**
     * A builder holding the program's agents, each with a new instance of its type's implementation
     * class (by its no-argument constructor, MASL §4), and its top-level block; the caller adds the
     * scheduler, journal and trace.
     *
     * @throws AgentCreationException if an implementation class cannot be loaded or instantiated
     */
    public Mission.Builder newMission() {
        try {
            return program().configure(Mission.builder(), this::newImplementation);
        } catch (IllegalStateException | ClassCastException e) {
            throw new AgentCreationException(e.getMessage(), e);
        }
    }

    /**
     * A new instance of an agent's implementation class, loaded along the agent path.
     *
     * @throws ReflectiveOperationException if the class is missing or has no usable constructor; an
     *     {@link AgentClasses.CreationFailed} if its static initialiser or its constructor threw (it names what)
     */
    public AgentImplementation newImplementation(MissionProgram.AgentSpec agent) throws ReflectiveOperationException {
        return AgentClasses.instantiate(agent.typeClassName(), classes);
    }

    /** An agent's implementation could not be created: its class is missing or has no usable constructor. */
    public static final class AgentCreationException extends RuntimeException {
        private static final long serialVersionUID = 1L;

        AgentCreationException(String message, Throwable cause) {
            super(message, cause);
        }
    }
}
