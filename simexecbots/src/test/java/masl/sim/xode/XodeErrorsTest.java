package masl.sim.xode;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Every malformed or unknown thing is an XodeException naming file, line, column and element. */
class XodeErrorsTest {

    private static final int LINE = Xode.HEADER_LINES + 1;

    private static XodeException failure(String spaceContent) {
        return Xode.failure(Xode.inSpace(spaceContent), LoadOptions.defaults());
    }

    private static XodeException strictFailure(String spaceContent) {
        return Xode.failure(Xode.inSpace(spaceContent), LoadOptions.strictMode());
    }

    private static void assertSingle(XodeException e, int line, int column, String element, String fragment) {
        assertEquals(1, e.problems().size(), e::getMessage);
        assertProblem(e, 0, line, column, element, fragment);
    }

    private static void assertProblem(XodeException e, int index, int line, int column, String element, String fragment) {
        XodeProblem problem = e.problems().get(index);
        assertEquals(new SourceLocation("test.xode", line, column), problem.location(), e::getMessage);
        assertEquals(element, problem.element(), e::getMessage);
        assertTrue(problem.message().contains(fragment), () -> "expected '" + fragment + "' in: " + e.getMessage());
        String prefix = "test.xode:" + line + ":" + column + ": error: " + (element.isEmpty() ? "" : "<" + element + ">: ");
        assertTrue(e.getMessage().contains(prefix), () -> "expected '" + prefix + "' in: " + e.getMessage());
    }

    @Test
    void malformedXmlIsLocated() {
        XodeException e = Xode.failure("<xode version=\"1.0r23\">\n<world>\n</xode>\n", LoadOptions.defaults());
        assertSingle(e, 3, 6, "", "malformed XML: Unexpected close tag </xode>; expected </world>");
    }

    @Test
    void missingRequiredAttribute() {
        assertSingle(failure("<geom><sphere/></geom>"), LINE, 7, "sphere", "missing required attribute 'radius'");
    }

    @Test
    void badNumber() {
        assertSingle(failure("<geom>\n  <box sizex=\"1\" sizey=\"two\" sizez=\"3\"/></geom>"), LINE + 1, 3, "box",
                "attribute 'sizey' must be a decimal number, found 'two'");
    }

    @Test
    void nonFiniteNumbersAreNotNumbers() {
        assertSingle(failure("<geom><sphere radius=\"NaN\"/></geom>"), LINE, 7, "sphere", "must be a decimal number");
    }

    @Test
    void sizeMustBePositive() {
        assertSingle(failure("<geom><cylinder radius=\"-1\" length=\"1\"/></geom>"), LINE, 7, "cylinder",
                "'radius' must be greater than 0");
    }

    @Test
    void linkToUnknownBody() {
        assertSingle(failure("<body name=\"a\">\n<joint><link1 body=\"ghost\"/><ball/></joint></body>"), LINE + 1, 8, "link1",
                "no body named 'ghost'");
    }

    @Test
    void geomWithTwoShapes() {
        assertSingle(failure("<geom><sphere radius=\"1\"/><box sizex=\"1\" sizey=\"1\" sizez=\"1\"/></geom>"), LINE, 1, "geom",
                "exactly one shape, found 2");
    }

    @Test
    void unknownElementIsAnErrorInStrictModeAndALocatedWarningOtherwise() throws XodeException {
        String content = "<body name=\"b\">\n    <wobble/></body>";
        assertSingle(strictFailure(content), LINE + 1, 5, "wobble", "unknown element inside <body>");
        LoadedModel lenient = Xode.loadSpace(content);
        assertEquals(1, lenient.warnings().size());
        assertEquals("test.xode:" + (LINE + 1) + ":5: warning: <wobble>: unknown element inside <body> (ignored)",
                lenient.warnings().get(0).format());
    }

    @Test
    void unknownAttributeInStrictMode() {
        assertSingle(strictFailure("<geom><sphere radius=\"1\" colour=\"red\"/></geom>"), LINE, 7, "sphere",
                "unknown attribute 'colour'");
    }

    @Test
    void knownElementInTheWrongPlace() {
        assertSingle(failure("<body><sphere radius=\"1\"/></body>"), LINE, 7, "sphere", "not allowed inside <body>");
    }

    @Test
    void hingeNeedsExactlyOneAxis() {
        assertSingle(failure("<body><joint><hinge><axis x=\"1\" y=\"0\" z=\"0\"/><axis x=\"0\" y=\"1\" z=\"0\"/></hinge></joint></body>"),
                LINE, 14, "hinge", "needs exactly 1 <axis>, found 2");
    }

    @Test
    void suspensionOnlyOnHinge2FirstAxis() {
        assertSingle(failure("<body><joint><hinge><axis x=\"1\" y=\"0\" z=\"0\" SuspensionERP=\"0.5\"/></hinge></joint></body>"),
                LINE, 21, "axis", "SuspensionERP exists only on the first axis of a hinge2 joint");
    }

    @Test
    void zeroAxis() {
        assertSingle(failure("<body><joint><slider><axis x=\"0\" y=\"0\" z=\"0\"/></slider></joint></body>"), LINE, 22, "axis",
                "must not be (0, 0, 0)");
    }

    @Test
    void jointLinkingNothing() {
        assertSingle(failure("<joint><ball/></joint>"), LINE, 1, "joint", "links nothing");
    }

    @Test
    void jointWithBothEndsOnOneBody() {
        assertSingle(failure("<body name=\"a\"/>\n<joint><link1 body=\"a\"/><link2 body=\"a\"/><fixed/></joint>"), LINE + 1, 1,
                "joint", "both ends of the joint are the same body");
    }

    @Test
    void duplicateNameUsedAsLinkTarget() {
        assertSingle(failure("<body name=\"a\"/>\n<body name=\"a\"/>\n<body><joint><link1 body=\"a\"/><ball/></joint></body>"),
                LINE + 1, 1, "body", "the name 'a' is already used at test.xode:" + LINE + ":1, and a joint links to it");
    }

    @Test
    void badBoolean() {
        assertSingle(failure("<body enabled=\"yes\"/>"), LINE, 1, "body", "attribute 'enabled' must be true or false");
    }

    @Test
    void rotationWithTwoForms() {
        assertSingle(failure("<body><transform><rotation><euler x=\"0\" y=\"0\" z=\"0\"/><quaternion x=\"0\" y=\"0\" z=\"0\" w=\"1\"/>"
                + "</rotation></transform></body>"), LINE, 18, "rotation", "exactly one of <euler>, <axisangle> or <quaternion>, found 2");
    }

    @Test
    void rootMustBeXode() {
        XodeException e = Xode.failure("<scene/>", LoadOptions.defaults());
        assertSingle(e, 1, 1, "scene", "the root element must be <xode>");
    }

    @Test
    void missingVersion() {
        XodeException e = Xode.failure("<xode><world><space/></world></xode>", LoadOptions.defaults());
        assertSingle(e, 1, 1, "xode", "missing required attribute 'version'");
    }

    @Test
    void everyErrorOfAFileIsReportedInDocumentOrder() {
        XodeException e = failure("<geom><sphere/></geom>\n<geom><box sizex=\"1\" sizey=\"x\" sizez=\"1\"/></geom>\n"
                + "<body><joint><link1 body=\"nobody\"/><ball/></joint></body>");
        assertEquals(3, e.problems().size(), e::getMessage);
        assertProblem(e, 0, LINE, 7, "sphere", "radius");
        assertProblem(e, 1, LINE + 1, 7, "box", "sizey");
        assertProblem(e, 2, LINE + 2, 14, "link1", "nobody");
        assertEquals(3, e.getMessage().lines().count());
    }

    @Test
    void unreadableSourceIsAnXodeException() {
        XodeException e = assertThrows(XodeException.class,
                () -> new XodeLoader().load(XodeSource.resource("masl/sim/robots/no-such-robot.xode")));
        assertEquals(1, e.problems().size());
        assertEquals("masl/sim/robots/no-such-robot.xode:1:1: error: cannot read the file: no such resource on the class path",
                e.getMessage());
    }
}
