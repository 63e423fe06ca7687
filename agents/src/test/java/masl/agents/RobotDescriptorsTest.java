package masl.agents;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.descriptor.AgentType;
import masl.runtime.descriptor.DescriptorLoader;
import masl.runtime.descriptor.PermeabilityState;
import masl.runtime.descriptor.Primitive;
import org.junit.jupiter.api.Test;

/** The shipped robot descriptors load from the classpath and match their implementation classes. */
class RobotDescriptorsTest {

    private final DescriptorLoader loader = new DescriptorLoader(AgentPath.parse(""));

    @Test
    void wheeledRobotDeclaresDriveSensorsOdometryAndBattery() {
        AgentType type = loader.load(loader.agentPath().find("WheeledRobot.xml", null).orElseThrow());
        assertEquals("masl.agents.WheeledRobot", type.fullClassName());
        assertEquals(DescriptorLoader.ROOT_TYPE, type.supertype().fullClassName());
        assertEquals(List.of("getProxyID", "nop", "log", "logln", "sleep", "setSpeeds", "stop", "getProximity", "getX", "getY", "getHeading", "getBattery"),
                type.primitives().stream().map(Primitive::name).toList());
        assertTrue(type.findPrimitive("getProximity").orElseThrow().accessor());
        assertFalse(type.findPrimitive("setSpeeds").orElseThrow().accessor());
        assertEquals(List.of("nothing", "default", "degraded"), type.states().stream().map(PermeabilityState::name).toList());
        assertEquals("default", type.initialState().orElseThrow().name());
    }

    @Test
    void degradedWheeledRobotCanBeReadButNotCommandedByOthers() {
        AgentType type = loader.loadByClassName("masl.agents.WheeledRobot");
        PermeabilityState degraded = type.findState("degraded").orElseThrow();
        String setSpeeds = type.findPrimitive("setSpeeds").orElseThrow().memberId();
        String battery = type.findPrimitive("getBattery").orElseThrow().memberId();
        assertEquals(0, degraded.rights(setSpeeds));
        assertEquals(0111, degraded.rights(battery));
    }

    @Test
    void maamAtomDeclaresServosContactAndLatches() {
        AgentType type = loader.load(loader.agentPath().find("MaamAtom.xml", null).orElseThrow());
        assertEquals("masl.agents.MaamAtom", type.fullClassName());
        assertEquals(List.of("getProxyID", "nop", "log", "logln", "sleep", "setJoint", "getJoint", "isOnGround", "attach", "detach", "isAttached"),
                type.primitives().stream().map(Primitive::name).toList());
        assertEquals(List.of("int", "int", "double"),
                type.findPrimitive("setJoint").orElseThrow().parameters().stream().map(p -> p.type()).toList());
    }
}
