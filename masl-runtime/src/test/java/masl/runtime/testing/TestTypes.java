package masl.runtime.testing;

import java.net.URISyntaxException;
import java.nio.file.Path;
import java.util.List;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.DescriptorLoader;

/** The agent types of the runtime tests, loaded from the test resources' {@code agents/} folder. */
public final class TestTypes {

    private static final String ROOT = TestAgent.class.getName();

    private TestTypes() {
    }

    /** {@code agents/Default.xml}: the root type of the tests, with its permeability states. */
    public static AgentType testAgent() {
        return loader().load(folder().resolve("Default.xml"));
    }

    /** {@code agents/TestRobot.xml}: a subtype of {@link #testAgent()} with a static primitive. */
    public static AgentType testRobot() {
        return loader().load(folder().resolve("TestRobot.xml"));
    }

    private static DescriptorLoader loader() {
        return new DescriptorLoader(AgentPath.of(List.of(folder()), TestTypes.class.getClassLoader()), ROOT);
    }

    /** The folder of the tests' descriptors, where {@link MaslProgram}s are translated. */
    static Path folder() {
        try {
            return Path.of(TestTypes.class.getResource("/agents/Default.xml").toURI()).getParent();
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
    }
}
