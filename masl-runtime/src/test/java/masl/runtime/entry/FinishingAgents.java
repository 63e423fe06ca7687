package masl.runtime.entry;

import masl.runtime.Agent;
import masl.runtime.AgentContext;
import masl.runtime.AgentProgram;
import masl.runtime.EntryDefinition;
import masl.runtime.Mission;
import masl.runtime.testing.TestAgent;

/**
 * A mission built, not run, whose agents' programs would finish at once: for tests that play a barrier by hand.
 * Written by hand: the tests play the barriers of their own {@code main}, which a translated program keeps to itself.
 */
final class FinishingAgents {

    final Mission mission;
    final Agent[] agents;

    FinishingAgents(EntryDefinition main, int count) {
        Mission.Builder builder = Mission.builder().main(main);
        TestAgent[] implementations = new TestAgent[count];
        for (int i = 0; i < count; i++) {
            implementations[i] = new TestAgent();
            builder.agent("a" + i, implementations[i], null, self -> new AgentProgram() {
                @Override
                protected void resume(AgentContext ctx) {
                    ctx.finish();
                }
            });
        }
        mission = builder.build();
        agents = new Agent[count];
        for (int i = 0; i < count; i++) {
            agents[i] = mission.agentOf(implementations[i]);
        }
    }
}
