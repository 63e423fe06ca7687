package masl.sim.scenario;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Function;
import masl.runtime.AgentImplementation;
import masl.runtime.AgentProgram;
import masl.runtime.EntryDefinition;
import masl.runtime.Mission;
import masl.runtime.MissionProgram;

/** A hand-written {@link MissionProgram}, as the translator would generate one, for runner tests. */
final class TestMission implements MissionProgram {

    private record Declared(AgentSpec spec, Function<AgentImplementation, AgentProgram> program) { }

    private final List<Declared> declared = new ArrayList<>();
    private EntryDefinition main;

    /** Sets the program's top-level block. */
    TestMission main(EntryDefinition block) {
        this.main = block;
        return this;
    }

    /** Declares the next agent: its name, type class and program. */
    TestMission agent(String name, Class<? extends AgentImplementation> type, Function<AgentImplementation, AgentProgram> program) {
        declared.add(new Declared(new AgentSpec(name, type.getName()), program));
        return this;
    }

    @Override
    public List<AgentSpec> agents() {
        return declared.stream().map(Declared::spec).toList();
    }

    @Override
    public Mission.Builder configure(Mission.Builder builder, ImplementationFactory implementations) {
        for (Declared agent : declared) {
            AgentImplementation implementation;
            try {
                implementation = implementations.create(agent.spec());
            } catch (ReflectiveOperationException e) {
                throw new IllegalStateException(e);
            }
            builder.agent(agent.spec().name(), implementation, agent.program());
        }
        return main == null ? builder : builder.main(main);
    }
}
