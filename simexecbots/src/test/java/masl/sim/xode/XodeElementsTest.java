package masl.sim.xode;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.ode4j.math.DVector3;
import org.ode4j.math.DVector3C;
import org.ode4j.ode.DAMotorJoint;
import org.ode4j.ode.DBallJoint;
import org.ode4j.ode.DBody;
import org.ode4j.ode.DBox;
import org.ode4j.ode.DCapsule;
import org.ode4j.ode.DCylinder;
import org.ode4j.ode.DFixedJoint;
import org.ode4j.ode.DGeom;
import org.ode4j.ode.DHinge2Joint;
import org.ode4j.ode.DHingeJoint;
import org.ode4j.ode.DJoint;
import org.ode4j.ode.DPlane;
import org.ode4j.ode.DRay;
import org.ode4j.ode.DSliderJoint;
import org.ode4j.ode.DSpace;
import org.ode4j.ode.DSphere;
import org.ode4j.ode.DTriMesh;
import org.ode4j.ode.DUniversalJoint;

/** One test per XODE element kind: what the loader creates is read back from ode4j. */
class XodeElementsTest {

    private static final double EPS = 1e-9;

    private static final String BODY_A = "<body name=\"a\"><transform><position x=\"1\" y=\"2\" z=\"3\"/></transform>"
            + "<mass><mass_shape density=\"1\"><sphere radius=\"0.5\"/></mass_shape></mass></body>";
    private static final String BODY_B = "<body name=\"b\"><transform><position x=\"2\" y=\"2\" z=\"3\"/></transform>"
            + "<mass><mass_shape density=\"1\"><sphere radius=\"0.5\"/></mass_shape></mass></body>";

    @Test
    void bodyHasPoseVelocitiesAndFlags() throws XodeException {
        LoadedModel model = Xode.loadSpace("""
                <body name="b" enabled="false" gravitymode="0">
                  <transform><position x="1" y="2" z="3"/></transform>
                  <linearVel x="0.5" y="0" z="0"/><angularVel x="0" y="0" z="2"/>
                  <force x="1" y="0" z="0"/><torque x="0" y="3" z="0"/>
                  <finiteRotation mode="1" xaxis="0" yaxis="0" zaxis="1"/>
                </body>""");
        DBody body = model.body("b");
        assertVector(1, 2, 3, body.getPosition());
        assertVector(0.5, 0, 0, body.getLinearVel());
        assertVector(0, 0, 2, body.getAngularVel());
        assertVector(1, 0, 0, body.getForce());
        assertVector(0, 3, 0, body.getTorque());
        assertFalse(body.isEnabled());
        assertFalse(body.getGravityMode());
        assertTrue(body.getFiniteRotationMode());
        assertEquals("b", body.getData());
    }

    @Test
    void bodyWithoutMassKeepsEngineDefault() throws XodeException {
        DBody body = Xode.loadSpace("<body name=\"b\"/>").body("b");
        assertEquals(1.0, body.getMass().getMass(), EPS);
    }

    @Test
    void massShapeWithDensityAndWithTotal() throws XodeException {
        LoadedModel model = Xode.loadSpace("""
                <body name="dense"><mass><mass_shape density="2"><box sizex="1" sizey="2" sizez="3"/></mass_shape></mass></body>
                <body name="total"><mass><mass_shape total="5" density="2"><cylinder radius="1" length="2"/></mass_shape></mass></body>
                <body name="capsule"><mass><mass_shape density="1"><cappedCylinder radius="1" length="2"/></mass_shape></mass></body>""");
        assertEquals(12.0, model.body("dense").getMass().getMass(), EPS);
        assertEquals(12.0 / 12 * (4 + 9), model.body("dense").getMass().getI().get00(), EPS);
        assertEquals(5.0, model.body("total").getMass().getMass(), EPS, "total wins over density");
        assertEquals(Math.PI * 2 + 4.0 / 3 * Math.PI, model.body("capsule").getMass().getMass(), EPS);
    }

    @Test
    void massStructNestedMassesAndAdjust() throws XodeException {
        LoadedModel model = Xode.loadSpace("""
                <body name="struct"><mass><mass_struct total="3">
                  <imatrix m00="1" m01="0" m02="0" m10="0" m11="2" m12="0" m20="0" m21="0" m22="3"/>
                </mass_struct></mass></body>
                <body name="nested"><mass>
                  <mass name="left"><transform><position x="-1" y="0" z="0"/></transform>
                    <mass_shape total="1"><sphere radius="0.1"/></mass_shape></mass>
                  <mass name="right"><transform><position x="1" y="0" z="0"/></transform>
                    <mass_shape total="1"><sphere radius="0.1"/></mass_shape></mass>
                  <adjust total="4"/>
                </mass></body>""");
        assertEquals(3.0, model.body("struct").getMass().getMass(), EPS);
        assertEquals(2.0, model.body("struct").getMass().getI().get11(), EPS);
        DBody nested = model.body("nested");
        assertEquals(4.0, nested.getMass().getMass(), EPS);
        // two point-like masses at x = ±1: inertia about Y dominated by 4·1²
        assertEquals(4.0 + 4 * 0.4 * 0.01, nested.getMass().getI().get11(), 1e-6);
    }

    @Test
    void offCentreMassMovesBodyToCentreAndKeepsGeomsInPlace() throws XodeException {
        LoadedModel model = Xode.loadSpace("""
                <body name="b">
                  <mass><transform><position x="0.5" y="0" z="0"/></transform>
                    <mass_shape total="1"><sphere radius="0.1"/></mass_shape></mass>
                  <geom name="g"><box sizex="1" sizey="1" sizez="1"/></geom>
                </body>""");
        assertVector(0.5, 0, 0, model.body("b").getPosition());
        assertVector(0, 0, 0, model.body("b").getMass().getC());
        assertVector(0, 0, 0, model.geom("g").getPosition());
    }

    @Test
    void primitiveGeomsHaveTheirSizes() throws XodeException {
        LoadedModel model = Xode.loadSpace("""
                <geom name="box"><box sizex="1" sizey="2" sizez="3"/></geom>
                <geom name="sphere"><sphere radius="0.5"/></geom>
                <geom name="cylinder"><cylinder radius="0.25" length="2"/></geom>
                <geom name="capsule"><cappedCylinder radius="0.3" length="1.5"/></geom>
                <geom name="ray"><ray length="4"/></geom>""");
        assertVector(1, 2, 3, ((DBox) model.geom("box")).getLengths());
        assertEquals(0.5, ((DSphere) model.geom("sphere")).getRadius(), EPS);
        assertEquals(0.25, ((DCylinder) model.geom("cylinder")).getRadius(), EPS);
        assertEquals(2.0, ((DCylinder) model.geom("cylinder")).getLength(), EPS);
        assertEquals(0.3, ((DCapsule) model.geom("capsule")).getRadius(), EPS);
        assertEquals(1.5, ((DCapsule) model.geom("capsule")).getLength(), EPS);
        assertEquals(4.0, ((DRay) model.geom("ray")).getLength(), EPS);
    }

    @Test
    void planeIsStaticWithItsEquation() throws XodeException {
        DPlane plane = (DPlane) Xode.loadSpace("<geom name=\"floor\"><plane a=\"0\" b=\"0\" c=\"1\" d=\"-0.5\"/></geom>").geom("floor");
        assertVector(0, 0, 1, plane.getNormal());
        assertEquals(-0.5, plane.getDepth(), EPS);
        assertNull(plane.getBody());
    }

    @Test
    void trimeshReadsOneBasedIndices() throws XodeException {
        LoadedModel model = Xode.loadSpace("""
                <geom name="mesh"><trimesh>
                  <vertices><v x="0" y="0" z="0"/><v x="1" y="0" z="0"/><v x="0" y="1" z="0"/><v x="0" y="0" z="1"/></vertices>
                  <triangles><t ia="1" ib="3" ic="2"/><t ia="1" ib="2" ic="4"/></triangles>
                </trimesh></geom>""");
        DTriMesh mesh = (DTriMesh) model.geom("mesh");
        assertEquals(2, mesh.getTriangleCount());
        DVector3 a = new DVector3();
        DVector3 b = new DVector3();
        DVector3 c = new DVector3();
        mesh.getTriangle(1, a, b, c);
        assertVector(0, 0, 0, a);
        assertVector(1, 0, 0, b);
        assertVector(0, 0, 1, c);
        assertTrue(model.warnings().isEmpty());
    }

    @Test
    void geomUnderBodyIsAttachedWithOffset() throws XodeException {
        LoadedModel model = Xode.loadSpace("""
                <body name="b"><transform><position x="1" y="0" z="0"/></transform>
                  <geom name="g"><transform><position x="0" y="2" z="0"/></transform><sphere radius="0.1"/></geom>
                </body>
                <geom name="static"><transform><position x="5" y="0" z="0"/></transform><sphere radius="0.1"/></geom>""");
        DGeom attached = model.geom("g");
        assertSame(model.body("b"), attached.getBody());
        assertVector(0, 2, 0, attached.getOffsetPosition());
        assertVector(1, 2, 0, attached.getPosition());
        assertNull(model.geom("static").getBody());
        assertVector(5, 0, 0, model.geom("static").getPosition());
    }

    @Test
    void hingeHasAnchorAxisLimitsAndMotor() throws XodeException {
        LoadedModel model = Xode.loadSpace(BODY_A + BODY_B + """
                <joint name="j"><link1 body="a"/><link2 body="b"/>
                  <hinge><anchor x="1.5" y="2" z="3"/>
                    <axis x="0" y="0" z="2" LowStop="-0.5" HiStop="0.7" Vel="1.5" FMax="3" Bounce="0.1"/></hinge>
                </joint>""");
        DHingeJoint hinge = model.joint("j", DHingeJoint.class).orElseThrow();
        assertSame(model.body("a"), hinge.getBody(0));
        assertSame(model.body("b"), hinge.getBody(1));
        DVector3 v = new DVector3();
        hinge.getAnchor(v);
        assertVector(1.5, 2, 3, v);
        hinge.getAxis(v);
        assertVector(0, 0, 1, v);
        assertEquals(-0.5, hinge.getParam(DJoint.PARAM_N.dParamLoStop1), EPS);
        assertEquals(0.7, hinge.getParam(DJoint.PARAM_N.dParamHiStop1), EPS);
        assertEquals(1.5, hinge.getParam(DJoint.PARAM_N.dParamVel1), EPS);
        assertEquals(3.0, hinge.getParam(DJoint.PARAM_N.dParamFMax1), EPS);
        assertEquals(0.1, hinge.getParam(DJoint.PARAM_N.dParamBounce1), EPS);
    }

    @Test
    void hinge2HasTwoAxesAndSuspension() throws XodeException {
        LoadedModel model = Xode.loadSpace(BODY_A + BODY_B + """
                <joint name="j"><link1 body="a"/><link2 body="b"/>
                  <hinge2><anchor x="2" y="2" z="3"/>
                    <axis x="0" y="0" z="1" SuspensionERP="0.4" SuspensionCFM="0.01"/>
                    <axis x="0" y="1" z="0" FMax="2"/></hinge2>
                </joint>""");
        DHinge2Joint joint = model.joint("j", DHinge2Joint.class).orElseThrow();
        DVector3 v = new DVector3();
        joint.getAxis1(v);
        assertVector(0, 0, 1, v);
        joint.getAxis2(v);
        assertVector(0, 1, 0, v);
        assertEquals(0.4, joint.getParam(DJoint.PARAM_N.dParamSuspensionERP1), EPS);
        assertEquals(2.0, joint.getParam(DJoint.PARAM_N.dParamFMax2), EPS);
    }

    @Test
    void ballSliderUniversalFixedAndAmotor() throws XodeException {
        LoadedModel model = Xode.loadSpace(BODY_A + BODY_B + """
                <joint name="ball"><link1 body="a"/><link2 body="b"/><ball><anchor x="1.5" y="2" z="3"/></ball></joint>
                <joint name="slider"><link1 body="a"/><link2 body="b"/><slider><axis x="1" y="0" z="0" LowStop="-1" HiStop="1"/></slider></joint>
                <joint name="universal"><link1 body="a"/><link2 body="b"/>
                  <universal><anchor x="1.5" y="2" z="3"/><axis x="0" y="1" z="0"/><axis x="0" y="0" z="1"/></universal></joint>
                <joint name="fixed"><link1 body="a"/><link2 body="b"/><fixed/></joint>
                <joint name="motor"><link1 body="a"/><link2 body="b"/>
                  <amotor><axis x="1" y="0" z="0" FMax="1"/><axis x="0" y="1" z="0"/><axis x="0" y="0" z="1" Vel="2"/></amotor></joint>""");
        DVector3 v = new DVector3();
        model.joint("ball", DBallJoint.class).orElseThrow().getAnchor(v);
        assertVector(1.5, 2, 3, v);
        DSliderJoint slider = model.joint("slider", DSliderJoint.class).orElseThrow();
        slider.getAxis(v);
        assertVector(1, 0, 0, v);
        assertEquals(1.0, slider.getParam(DJoint.PARAM_N.dParamHiStop1), EPS);
        DUniversalJoint universal = model.joint("universal", DUniversalJoint.class).orElseThrow();
        universal.getAxis2(v);
        assertVector(0, 0, 1, v);
        assertTrue(model.joint("fixed", DFixedJoint.class).isPresent());
        DAMotorJoint motor = model.joint("motor", DAMotorJoint.class).orElseThrow();
        assertEquals(3, motor.getNumAxes());
        motor.getAxis(2, v);
        assertVector(0, 0, 1, v);
        assertEquals(1.0, motor.getParam(DJoint.PARAM_N.dParamFMax1), EPS);
        assertEquals(2.0, motor.getParam(DJoint.PARAM_N.dParamVel3), EPS);
    }

    @Test
    void jointLinksFollowEnclosingBodyAndEnvironmentRules() throws XodeException {
        LoadedModel model = Xode.loadSpace("""
                <joint name="forward"><link1 body="late"/><ball/></joint>
                <body name="outer">
                  <joint name="toWorld"><hinge><axis x="0" y="0" z="1"/></hinge></joint>
                  <joint name="toOuter"><link1 body="late"/><ball/></joint>
                </body>
                <body name="late"><transform><position x="1" y="0" z="0"/></transform></body>""");
        DJoint toWorld = model.joint("toWorld");
        assertSame(model.body("outer"), toWorld.getBody(0));
        assertNull(toWorld.getBody(1));
        DJoint toOuter = model.joint("toOuter");
        assertSame(model.body("late"), toOuter.getBody(0));
        assertSame(model.body("outer"), toOuter.getBody(1));
        assertSame(model.body("late"), model.joint("forward").getBody(0), "a link may name a body defined later");
    }

    @Test
    void anchorAndAxisAreInTheParentFrameUnlessAbsolute() throws XodeException {
        LoadedModel model = Xode.loadSpace("""
                <group><transform><position x="10" y="0" z="0"/>
                    <rotation><axisangle x="0" y="0" z="1" angle="90" aformat="degrees"/></rotation></transform>
                  <body name="b">
                    <joint name="relative"><hinge><anchor x="1" y="0" z="0"/><axis x="1" y="0" z="0"/></hinge></joint>
                    <joint name="absolute"><hinge><anchor x="1" y="0" z="0" absolute="true"/><axis x="1" y="0" z="0" absolute="true"/></hinge></joint>
                  </body>
                </group>""");
        DVector3 v = new DVector3();
        DHingeJoint relative = (DHingeJoint) model.joint("relative");
        relative.getAnchor(v);
        assertVector(10, 1, 0, v);
        relative.getAxis(v);
        assertVector(0, 1, 0, v);
        DHingeJoint absolute = (DHingeJoint) model.joint("absolute");
        absolute.getAnchor(v);
        assertVector(1, 0, 0, v);
        absolute.getAxis(v);
        assertVector(1, 0, 0, v);
    }

    @Test
    void spacesNestAndJointGroupsHoldTheirJoints() throws XodeException {
        LoadedModel model = Xode.loadSpace("""
                <space name="inner"><geom name="g"><sphere radius="1"/></geom></space>
                <jointgroup name="jg"><body name="b"><joint name="j"><ball/></joint></body></jointgroup>""");
        DSpace inner = model.space("inner").orElseThrow();
        assertSame(model.space("space").orElseThrow(), inner.getSpace());
        assertSame(inner, model.geom("g").getSpace());
        assertTrue(model.jointGroup("jg").isPresent());
        assertSame(model.body("b"), model.joint("j").getBody(0));
    }

    @Test
    void eachWorldElementGetsItsOwnOdeWorldAndRootSpace() throws XodeException {
        LoadedModel model = Xode.load("""
                <xode version="1.0r23"><world name="w1"><space><body name="a"/></space></world>
                <world name="w2"><transform><position x="0" y="0" z="10"/></transform><space><body name="b"/></space></world></xode>""");
        assertEquals(2, model.worlds().size());
        assertEquals("w2", model.worlds().get(1).name());
        assertSame(model.worlds().get(0).world(), model.body("a").getWorld());
        assertSame(model.worlds().get(1).world(), model.body("b").getWorld());
        assertNotSame(model.worlds().get(0).rootSpace(), model.worlds().get(1).rootSpace());
        assertVector(0, 0, 10, model.body("b").getPosition());
    }

    @Test
    void extensionsAreSkippedWherever() throws XodeException {
        LoadedModel model = Xode.load("""
                <xode version="1.0r23"><ext><anything goes="here"><deep/></anything></ext>
                <world><ext/><space><body name="b"><ext><mesh file="x.obj"/></ext>
                <geom name="g"><ext/><sphere radius="1"/></geom></body></space></world></xode>""");
        assertTrue(model.warnings().isEmpty());
        assertSame(model.body("b"), model.geom("g").getBody());
    }

    @Test
    void prefixesMakeNamesDistinctAndLinksFollowThem() throws XodeException {
        XodeLoader loader = new XodeLoader();
        XodeSource robot = XodeSource.resource("masl/agents/robots/wheeled-robot.xode");
        LoadedModel first = loader.load(robot, "khepera0.", LoadTarget.newWorlds());
        LoadedModel second = loader.load(robot, "khepera1.", LoadTarget.newWorlds());
        assertTrue(first.bodies().containsKey("khepera0.chassis"));
        assertTrue(second.bodies().containsKey("khepera1.chassis"));
        assertFalse(first.bodies().containsKey("chassis"));
        assertNotSame(first.body("khepera0.chassis"), second.body("khepera1.chassis"));
        assertSame(first.body("khepera0.chassis"), first.joint("khepera0.leftMotor").getBody(1), "link2 names the chassis");
        assertEquals("khepera1.leftMotor", second.joint("khepera1.leftMotor").getData());
    }

    static void assertVector(double x, double y, double z, DVector3C actual) {
        assertArrayEquals(new double[] {x, y, z}, new double[] {actual.get0(), actual.get1(), actual.get2()}, 1e-9,
                () -> "vector " + actual);
    }
}
