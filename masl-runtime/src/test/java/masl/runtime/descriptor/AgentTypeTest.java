package masl.runtime.descriptor;

import static masl.runtime.descriptor.TestDescriptors.FIXTURE_ROOT;
import static masl.runtime.descriptor.TestDescriptors.PREFIX;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/** A rich valid descriptor (the Khepera example) and what its AgentType says, inheritance included. */
class AgentTypeTest {

    private DescriptorLoader loader;
    private AgentType khepera;

    @BeforeEach
    void loadKhepera() {
        loader = TestDescriptors.loader();
        khepera = loader.load(TestDescriptors.fixtureFolder().resolve("Khepera.xml"));
    }

    @Test
    void identityAndSource() {
        assertEquals("Khepera", khepera.shortName());
        assertEquals(PREFIX + "Khepera", khepera.fullClassName());
        assertEquals(PREFIX + "Robot", khepera.superFullClassName());
        assertEquals(3, khepera.line());
        assertTrue(khepera.source().displayName().endsWith("Khepera.xml"), khepera.source().displayName());
        assertEquals(TestDescriptors.fixtureFolder().resolve("Khepera.xml"), khepera.source().file().orElseThrow());
    }

    @Test
    void supertypesAreResolvedAndTheRootIsImplicit() {
        AgentType robot = khepera.supertype();
        assertEquals(PREFIX + "Robot", robot.fullClassName());
        AgentType root = robot.supertype();
        assertEquals(FIXTURE_ROOT, root.fullClassName());
        assertEquals(FIXTURE_ROOT, robot.superFullClassName(), "Robot.xml names no supertype: the root is implied");
        assertNull(root.supertype());
        assertNull(root.superFullClassName());
        assertSame(robot, loader.loadByClassName(PREFIX + "Robot"), "types are cached by class name");
        assertSame(khepera, loader.load(TestDescriptors.fixtureFolder().resolve("Khepera.xml")));
    }

    @Test
    void subtypeRelation() {
        AgentType robot = khepera.supertype();
        assertTrue(khepera.isSubtypeOf(khepera));
        assertTrue(khepera.isSubtypeOf(robot));
        assertTrue(khepera.isSubtypeOf(robot.supertype()));
        assertFalse(robot.isSubtypeOf(khepera));
    }

    @Test
    void primitiveDetailsAreNormalised() {
        Primitive proximity = khepera.findPrimitive("getProximity").orElseThrow();
        assertEquals("P1", proximity.memberId());
        assertEquals("int", proximity.returnType());
        assertEquals(List.of(new Parameter("sensor", "int")), proximity.parameters());
        assertTrue(proximity.synchronous());
        assertTrue(proximity.accessor());
        assertNull(proximity.countermeasure());
        assertFalse(proximity.isStatic());
        assertEquals(14, proximity.line());
        assertEquals(3, proximity.column());
        assertEquals("int getProximity(int)", proximity.signature());

        Primitive gripper = khepera.findPrimitive("startGripper").orElseThrow();
        assertFalse(gripper.synchronous());
        assertFalse(gripper.accessor(), "accessor defaults to false");
        assertEquals("stopGripper", gripper.countermeasure());
        assertEquals(List.of("java.io.IOException"), gripper.exceptions());

        assertTrue(khepera.findPrimitive("instances").orElseThrow().isStatic());
        assertEquals("int[]", khepera.findPrimitive("readings").orElseThrow().returnType());
        assertEquals(List.of(new Parameter("target", PREFIX + "Vector2d"), new Parameter("speeds", "double[]")),
                khepera.findPrimitive("goTo").orElseThrow().parameters());
    }

    @Test
    void attributeDetails() {
        Attribute maxSpeed = khepera.findAttribute("MAX_SPEED").orElseThrow();
        assertEquals("A2", maxSpeed.memberId());
        assertEquals("double", maxSpeed.type());
        assertEquals("0.5", maxSpeed.value());
        assertTrue(maxSpeed.isStatic());
        assertTrue(maxSpeed.isFinal());
        assertEquals(7, maxSpeed.line());
        Attribute battery = khepera.findAttribute("battery").orElseThrow();
        assertNull(battery.value());
        assertFalse(battery.isStatic());
        assertFalse(battery.isFinal());
    }

    @Test
    void membersAreInheritedAndMayBeRedefined() {
        assertEquals("java.lang.String", khepera.findAttribute("name").orElseThrow().type(), "inherited from Robot");
        assertEquals("D3", khepera.findPrimitive("log").orElseThrow().memberId(), "inherited from the root");
        Primitive halt = khepera.findPrimitive("halt").orElseThrow();
        assertTrue(halt.synchronous(), "Khepera's redefinition, not Robot's asynchronous halt");
        assertFalse(khepera.supertype().findPrimitive("halt").orElseThrow().synchronous());
        assertTrue(khepera.findPrimitive("fly").isEmpty());
        assertTrue(khepera.findAttribute("log").isEmpty(), "a primitive is not an attribute");

        List<String> visible = khepera.primitives().stream().map(Primitive::name).toList();
        assertEquals(List.of("getProxyID", "nop", "log", "logln", "sleep", "move", "halt", "getProximity",
                "startGripper", "stopGripper", "instances", "readings", "position", "goTo"), visible);
        assertEquals(List.of("name", "battery", "MAX_SPEED", "count"),
                khepera.attributes().stream().map(Attribute::name).toList());
        assertEquals(8, khepera.declaredPrimitives().size());
        assertEquals(3, khepera.declaredAttributes().size());
    }

    @Test
    void utilityClassesAreInheritedThenOwn() {
        assertEquals(List.of(PREFIX + "Vector2d", "java.util.ArrayList"), khepera.utilityClasses());
        assertEquals(List.of(PREFIX + "Vector2d"), khepera.supertype().utilityClasses());
    }
}
