package masl.agents;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
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

    /** {@code default} allows everything but others calling {@code sleep}: an outsider must not pause an agent. */
    @Test
    void rootStatesAreNothingAndDefaultWhichAllowsEverythingButOthersSleeping() {
        AgentType root = loader.loadByClassName(DescriptorLoader.ROOT_TYPE);
        assertEquals(List.of("nothing", "default"), root.states().stream().map(PermeabilityState::name).toList());
        assertEquals("default", root.initialState().orElseThrow().name());
        PermeabilityState defaultState = root.findState("default").orElseThrow();
        for (Primitive primitive : root.primitives()) {
            assertEquals(primitive.name().equals("sleep") ? 0110 : 0777, defaultState.rights(primitive.memberId()),
                    primitive.name());
            assertEquals(0, root.findState("nothing").orElseThrow().rights(primitive.memberId()));
        }
        String sleep = root.findPrimitive("sleep").orElseThrow().memberId();
        assertTrue(defaultState.allows(sleep, PermeabilityState.Requester.SELF, PermeabilityState.INVOKE));
        assertTrue(defaultState.allows(sleep, PermeabilityState.Requester.GROUP, PermeabilityState.INVOKE));
        assertFalse(defaultState.allows(sleep, PermeabilityState.Requester.OTHER, PermeabilityState.INVOKE));
    }

    /** A subtype that declares no state of its own: its members all allowed in {@code default}, {@code sleep} not to others. */
    @Test
    void subtypesKeepEverythingButOthersSleeping() {
        AgentType robot = loader.loadByClassName("masl.agents.WheeledRobot");
        PermeabilityState defaultState = robot.findState("default").orElseThrow();
        for (Primitive primitive : robot.primitives()) {
            assertEquals(primitive.name().equals("sleep") ? 0110 : 0777, defaultState.rights(primitive.memberId()),
                    primitive.name());
        }
    }
}
