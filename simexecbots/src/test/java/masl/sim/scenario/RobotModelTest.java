package masl.sim.scenario;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import masl.runtime.descriptor.AgentPath;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.DescriptorLoader;
import org.junit.jupiter.api.Test;

/** Each robot model names a shipped descriptor of its own implementation class. */
class RobotModelTest {

    @Test
    void everyModelsDescriptorDeclaresItsClass() {
        DescriptorLoader loader = new DescriptorLoader(AgentPath.parse(""));
        for (RobotModel model : RobotModel.values()) {
            AgentType type = loader.load(loader.agentPath().find(model.descriptor(), null).orElseThrow());
            assertEquals(model.implementation().getName(), type.fullClassName(), model.name());
            assertEquals(model, RobotModel.named(model.scenarioName()).orElseThrow());
        }
        assertTrue(RobotModel.named("tank").isEmpty());
    }
}
