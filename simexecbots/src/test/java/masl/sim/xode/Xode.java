package masl.sim.xode;

/** Builds small XODE documents for tests; the header puts the space's content on line 4. */
final class Xode {

    /** Lines before the first line of {@code spaceContent}. */
    static final int HEADER_LINES = 3;

    private Xode() {
    }

    static String inSpace(String spaceContent) {
        return "<xode version=\"1.0r23\" name=\"test\">\n<world>\n<space name=\"space\">\n"
                + spaceContent + "\n</space>\n</world>\n</xode>\n";
    }

    static LoadedModel load(String xml) throws XodeException {
        return new XodeLoader().load(XodeSource.text("test.xode", xml));
    }

    static LoadedModel loadSpace(String spaceContent) throws XodeException {
        return load(inSpace(spaceContent));
    }

    static XodeException failure(String xml, LoadOptions options) {
        try {
            new XodeLoader(options).load(XodeSource.text("test.xode", xml));
        } catch (XodeException e) {
            return e;
        }
        throw new AssertionError("expected an XodeException for:\n" + xml);
    }
}
