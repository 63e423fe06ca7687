package masl.agents;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.DescriptorLoader;
import masl.runtime.descriptor.DescriptorSource;
import masl.runtime.descriptor.PermeabilityState;
import masl.runtime.descriptor.Primitive;
import org.junit.jupiter.api.Test;

/** The shipped Default.xml, found as a classpath resource, validates against masl.agents.Default. */
class DefaultDescriptorTest {

    private final DescriptorLoader loader = new DescriptorLoader(AgentPath.parse(""));

    @Test
    void shippedDefaultIsFoundOnTheClasspathAndMatchesItsClass() {
        DescriptorSource source = loader.agentPath().find("Default.xml", null).orElseThrow();
        assertEquals("classpath:Default.xml", source.displayName());
        AgentType root = loader.load(source);
        assertEquals("Default", root.shortName());
        assertEquals(DescriptorLoader.ROOT_TYPE, root.fullClassName());
        assertNull(root.supertype());
        assertEquals(List.of("getProxyID", "nop", "log", "logln", "sleep"),
                root.primitives().stream().map(Primitive::name).toList());
        assertTrue(root.primitives().stream().allMatch(Primitive::synchronous));
        assertTrue(root.findPrimitive("getProxyID").orElseThrow().accessor());
        assertEquals("long", root.findPrimitive("sleep").orElseThrow().parameters().get(0).type());
    }

    @Test
    void rootStatesAreNothingAndDefaultWhichAllowsEverything() {
        AgentType root = loader.loadByClassName(DescriptorLoader.ROOT_TYPE);
        assertEquals(List.of("nothing", "default"), root.states().stream().map(PermeabilityState::name).toList());
        assertEquals("default", root.initialState().orElseThrow().name());
        for (Primitive primitive : root.primitives()) {
            assertEquals(0777, root.findState("default").orElseThrow().rights(primitive.memberId()));
            assertEquals(0, root.findState("nothing").orElseThrow().rights(primitive.memberId()));
        }
    }
}
