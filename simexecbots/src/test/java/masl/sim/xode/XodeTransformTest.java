package masl.sim.xode;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.ode4j.math.DMatrix3C;
import org.ode4j.ode.DBody;

/** The transform forms of xode.md §3 and §10.1–10.3, compared through the poses ode4j receives. */
class XodeTransformTest {

    private static final double EPS = 1e-9;

    private static DBody bodyWithRotation(String rotation) throws XodeException {
        return Xode.loadSpace("<body name=\"b\"><transform><rotation>" + rotation + "</rotation></transform></body>").body("b");
    }

    private static double[] rows(DMatrix3C m) {
        return new double[] {m.get00(), m.get01(), m.get02(), m.get10(), m.get11(), m.get12(), m.get20(), m.get21(), m.get22()};
    }

    @Test
    void eulerAxisAngleQuaternionAndMatrixAgreeOnOneRotation() throws XodeException {
        // 90° about Z
        double h = Math.sqrt(0.5);
        double[] expected = {0, -1, 0, 1, 0, 0, 0, 0, 1};
        assertArrayEquals(expected, rows(bodyWithRotation("<euler x=\"0\" y=\"0\" z=\"90\" aformat=\"degrees\"/>").getRotation()), EPS);
        assertArrayEquals(expected, rows(bodyWithRotation("<euler x=\"0\" y=\"0\" z=\"" + Math.PI / 2 + "\"/>").getRotation()), EPS);
        assertArrayEquals(expected, rows(bodyWithRotation("<axisangle x=\"0\" y=\"0\" z=\"3\" angle=\"90\" aformat=\"DEGREES\"/>")
                .getRotation()), EPS);
        assertArrayEquals(expected, rows(bodyWithRotation("<quaternion w=\"" + h + "\" x=\"0\" y=\"0\" z=\"" + h + "\"/>")
                .getRotation()), EPS);
        DBody matrix = Xode.loadSpace("<body name=\"b\"><transform><matrix4f m00=\"0\" m01=\"-1\" m02=\"0\" m03=\"0\""
                + " m10=\"1\" m11=\"0\" m12=\"0\" m13=\"0\" m20=\"0\" m21=\"0\" m22=\"1\" m23=\"0\""
                + " m30=\"0\" m31=\"0\" m32=\"0\" m33=\"1\"/></transform></body>").body("b");
        assertArrayEquals(expected, rows(matrix.getRotation()), EPS);
    }

    @Test
    void eulerComposesAsRxRyRz() throws XodeException {
        double a = 0.3;
        double b = -0.7;
        double c = 1.1;
        DBody euler = bodyWithRotation("<euler x=\"" + a + "\" y=\"" + b + "\" z=\"" + c + "\"/>");
        Pose expected = Pose.axisAngle(1, 0, 0, a).compose(Pose.axisAngle(0, 1, 0, b)).compose(Pose.axisAngle(0, 0, 1, c));
        assertArrayEquals(expected.rotationMatrix(), rows(euler.getRotation()), EPS);
    }

    @Test
    void pyodeConventionNegatesTheAngles() throws XodeException {
        String xml = Xode.inSpace("<body name=\"b\"><transform><rotation><euler x=\"0.3\" y=\"0.2\" z=\"0.1\"/></rotation></transform></body>");
        DBody body = new XodeLoader(LoadOptions.defaults().withEuler(EulerConvention.PYODE_COMPATIBLE))
                .load(XodeSource.text("t.xode", xml)).body("b");
        Pose expected = Pose.axisAngle(1, 0, 0, -0.3).compose(Pose.axisAngle(0, 1, 0, -0.2)).compose(Pose.axisAngle(0, 0, 1, -0.1));
        assertArrayEquals(expected.rotationMatrix(), rows(body.getRotation()), EPS);
    }

    @Test
    void nestedTransformsComposeAndAbsoluteResets() throws XodeException {
        LoadedModel model = Xode.loadSpace("""
                <body name="parent"><transform><position x="1" y="0" z="0"/>
                    <rotation><axisangle x="0" y="0" z="1" angle="1.5707963267948966"/></rotation></transform>
                  <body name="child"><transform><position x="2" y="0" z="0"/></transform>
                    <body name="grandchild"><transform absolute="true"><position x="7" y="8" z="9"/></transform></body>
                  </body>
                </body>""");
        XodeElementsTest.assertVector(1, 2, 0, model.body("child").getPosition());
        assertArrayEquals(rows(model.body("parent").getRotation()), rows(model.body("child").getRotation()), EPS);
        XodeElementsTest.assertVector(7, 8, 9, model.body("grandchild").getPosition());
        assertArrayEquals(new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1}, rows(model.body("grandchild").getRotation()), EPS);
    }

    @Test
    void rowVectorMatrixIsTransposed() throws XodeException {
        DBody body = Xode.loadSpace("<body name=\"b\"><transform><matrix m00=\"1\" m01=\"0\" m02=\"0\" m03=\"0\""
                + " m10=\"0\" m11=\"1\" m12=\"0\" m13=\"0\" m20=\"0\" m21=\"0\" m22=\"1\" m23=\"0\""
                + " m30=\"4\" m31=\"5\" m32=\"6\" m33=\"1\"/></transform></body>").body("b");
        XodeElementsTest.assertVector(4, 5, 6, body.getPosition());
    }

    @Test
    void scaleIsIgnoredWithAWarning() throws XodeException {
        LoadedModel model = Xode.loadSpace("<body name=\"b\"><transform scale=\"2\"><position x=\"1\" y=\"0\" z=\"0\"/></transform></body>");
        XodeElementsTest.assertVector(1, 0, 0, model.body("b").getPosition());
        assertEquals(1, model.warnings().size());
        assertTrue(model.warnings().get(0).message().contains("scale 2.0 is ignored"));
    }

    @Test
    void planeUnderTransformGetsAWorldEquation() throws XodeException {
        LoadedModel model = Xode.loadSpace("<group><transform><position x=\"0\" y=\"0\" z=\"2\"/></transform>"
                + "<geom name=\"p\"><plane a=\"0\" b=\"0\" c=\"1\" d=\"0\"/></geom></group>");
        assertEquals(2.0, ((org.ode4j.ode.DPlane) model.geom("p")).getDepth(), EPS);
        assertEquals(1, model.warnings().size());
    }
}
