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
        assertEquals("masl.agents.Robot", type.supertype().fullClassName());
        assertEquals(List.of("getProxyID", "nop", "log", "logln", "sleep", "stop", "getX", "getY", "getHeading", "getBattery", "getPosition", "setSpeeds", "getProximity"),
                type.primitives().stream().map(Primitive::name).toList());
        assertTrue(type.findPrimitive("getProximity").orElseThrow().accessor());
        assertFalse(type.findPrimitive("setSpeeds").orElseThrow().accessor());
        assertEquals(List.of("nothing", "default", "degraded", "dead"), type.states().stream().map(PermeabilityState::name).toList());
        assertEquals("default", type.initialState().orElseThrow().name());
    }

    @Test
    void degradedWheeledRobotCanBeReadAndStoppedButNotCommanded() {
        AgentType type = loader.loadByClassName("masl.agents.WheeledRobot");
        PermeabilityState degraded = type.findState("degraded").orElseThrow();
        assertEquals(0, degraded.rights(memberId(type, "setSpeeds")));
        assertEquals(0111, degraded.rights(memberId(type, "getBattery")));
        assertEquals(0111, degraded.rights(memberId(type, "getProximity")));
        assertEquals(0111, degraded.rights(memberId(type, "stop")));
    }

    @Test
    void robotIsTheSupertypeOfEveryWheeledType() {
        AgentType robot = loader.load(loader.agentPath().find("Robot.xml", null).orElseThrow());
        assertEquals(List.of("getProxyID", "nop", "log", "logln", "sleep", "stop", "getX", "getY", "getHeading", "getBattery", "getPosition"),
                robot.primitives().stream().map(Primitive::name).toList());
        assertEquals(List.of("masl.agents.Position"), robot.utilityClasses());
        for (String subtype : List.of("masl.agents.WheeledRobot", "masl.agents.SoftWheeledRobot", "masl.agents.Scout")) {
            assertTrue(loader.loadByClassName(subtype).isSubtypeOf(robot), subtype);
        }
        assertTrue(loader.loadByClassName("masl.agents.Scout").isSubtypeOf(loader.loadByClassName("masl.agents.SoftWheeledRobot")));
    }

    @Test
    void softWheeledRobotDeclaresMotionAndAnAsynchronousCalibrationWithItsCountermeasure() {
        AgentType type = loader.load(loader.agentPath().find("SoftWheeledRobot.xml", null).orElseThrow());
        Primitive calibrate = type.findPrimitive("calibrate").orElseThrow();
        assertFalse(calibrate.synchronous());
        assertEquals("abortCalibration", calibrate.countermeasure());
        assertEquals("boolean", calibrate.returnType());
        assertTrue(type.findPrimitive("getPosition").isPresent());
        assertEquals("5", type.findAttribute("MOVE_COST").orElseThrow().value());
        assertTrue(type.findAttribute("MOVE_COST").orElseThrow().isStatic());
        assertEquals(List.of("nothing", "default", "degraded", "dead"), type.states().stream().map(PermeabilityState::name).toList());
    }

    @Test
    void degradedSoftRobotDrivesItselfOnlyAndADeadOneMayOnlyBeRead() {
        AgentType type = loader.loadByClassName("masl.agents.SoftWheeledRobot");
        PermeabilityState degraded = type.findState("degraded").orElseThrow();
        PermeabilityState dead = type.findState("dead").orElseThrow();
        assertEquals(0100, degraded.rights(memberId(type, "moveForward")));
        assertEquals(0, degraded.rights(memberId(type, "calibrate")));
        assertEquals(0111, degraded.rights(memberId(type, "abortCalibration")));
        assertEquals(0111, degraded.rights(memberId(type, "stop")));
        assertEquals(0, dead.rights(memberId(type, "moveForward")));
        assertEquals(0, dead.rights(memberId(type, "stop")));
        assertEquals(0111, dead.rights(memberId(type, "getBattery")));
        assertEquals(0100, dead.rights(memberId(type, "logln")));
        assertEquals(0777, type.findState("default").orElseThrow().rights(memberId(type, "moveForward")));
    }

    @Test
    void scoutRedefinesMoveForwardUnderItsInheritedIdAndAddsAScan() {
        AgentType scout = loader.load(loader.agentPath().find("Scout.xml", null).orElseThrow());
        AgentType soft = scout.supertype();
        assertEquals("masl.agents.SoftWheeledRobot", soft.fullClassName());
        assertEquals(memberId(soft, "moveForward"), memberId(scout, "moveForward"));
        assertEquals("masl.agents.Scout", scout.fullClassName());
        assertTrue(soft.findPrimitive("scan").isEmpty());
        assertEquals(0111, scout.findState("degraded").orElseThrow().rights(memberId(scout, "scan")));
        assertEquals(0100, scout.findState("degraded").orElseThrow().rights(memberId(scout, "moveForward")));
        assertEquals(0, scout.findState("dead").orElseThrow().rights(memberId(scout, "scan")));
    }

    private static String memberId(AgentType type, String primitive) {
        return type.findPrimitive(primitive).orElseThrow().memberId();
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
