package masl.sim.xode;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.ode4j.ode.DCapsule;
import org.ode4j.ode.DTriMesh;

/** What xode.md §10 lets a lenient load work around: each is a located warning, an error in strict mode. */
class XodeWarningsTest {

    private static final int LINE = Xode.HEADER_LINES + 1;

    private static void assertWarnedAndStrictFails(String spaceContent, int line, int column, String fragment) throws XodeException {
        LoadedModel model = Xode.loadSpace(spaceContent);
        assertEquals(1, model.warnings().size(), model.warnings()::toString);
        XodeProblem warning = model.warnings().get(0);
        assertEquals(new SourceLocation("test.xode", line, column), warning.location());
        assertTrue(warning.message().contains(fragment), warning::format);
        XodeException strict = Xode.failure(Xode.inSpace(spaceContent), LoadOptions.strictMode());
        assertTrue(strict.getMessage().contains("test.xode:" + line + ":" + column + ": error:"), strict::getMessage);
    }

    @Test
    void coneIsSkipped() throws XodeException {
        assertWarnedAndStrictFails("<geom name=\"c\"><cone radius=\"1\" length=\"2\"/></geom>", LINE, 16, "ode4j has no cone");
        assertTrue(Xode.loadSpace("<geom name=\"c\"><cone radius=\"1\" length=\"2\"/></geom>").geoms().isEmpty());
    }

    @Test
    void zeroBasedTrimeshIndices() throws XodeException {
        String mesh = "<geom name=\"m\"><trimesh><vertices><v x=\"0\" y=\"0\" z=\"0\"/><v x=\"1\" y=\"0\" z=\"0\"/>"
                + "<v x=\"0\" y=\"1\" z=\"0\"/></vertices><triangles><t ia=\"0\" ib=\"1\" ic=\"2\"/></triangles></trimesh></geom>";
        assertWarnedAndStrictFails(mesh, LINE, 16, "read as 0-based");
        assertEquals(1, ((DTriMesh) Xode.loadSpace(mesh).geom("m")).getTriangleCount());
    }

    @Test
    void massShapeWithoutDensityOrTotalUsesDensityOne() throws XodeException {
        String body = "<body name=\"b\"><mass><mass_shape><box sizex=\"1\" sizey=\"2\" sizez=\"3\"/></mass_shape></mass></body>";
        assertWarnedAndStrictFails(body, LINE, 22, "density 1 is used");
        assertEquals(6.0, Xode.loadSpace(body).body("b").getMass().getMass(), 1e-12);
    }

    @Test
    void duplicateNameThatNoJointLinksTo() throws XodeException {
        assertWarnedAndStrictFails("<geom name=\"g\"><sphere radius=\"1\"/></geom>\n<geom name=\"g\"><sphere radius=\"2\"/></geom>",
                LINE + 1, 1, "already used at test.xode:" + LINE + ":1");
    }

    @Test
    void motorParametersOde4jWouldIgnore() throws XodeException {
        assertWarnedAndStrictFails("<body><joint><hinge><axis x=\"1\" y=\"0\" z=\"0\" FMax=\"-1\"/></hinge></joint></body>", LINE, 21,
                "FMax must not be negative");
    }

    @Test
    void capsuleIsAnAliasOfCappedCylinder() throws XodeException {
        LoadedModel model = Xode.loadSpace("<geom name=\"c\"><capsule radius=\"0.5\" length=\"1\"/></geom>");
        assertEquals(0.5, ((DCapsule) model.geom("c")).getRadius(), 1e-12);
        assertTrue(model.warnings().isEmpty());
    }

    @Test
    void otherRevisionIsANoticeEvenInStrictModeButOtherMajorIsNot() throws XodeException {
        String revision = "<xode version=\"1.0r21\"><world><space/></world></xode>";
        List<XodeProblem> notices = new XodeLoader(LoadOptions.strictMode()).load(XodeSource.text("test.xode", revision)).warnings();
        assertEquals(1, notices.size());
        assertTrue(notices.get(0).message().contains("version 1.0r21 read as 1.0r23"));
        String major = "<xode version=\"2.0\"><world><space/></world></xode>";
        assertEquals(1, Xode.load(major).warnings().size());
        XodeException strict = Xode.failure(major, LoadOptions.strictMode());
        assertTrue(strict.getMessage().contains("test.xode:1:1: error: <xode>: version 2.0 is not XODE 1.0"), strict::getMessage);
    }
}
