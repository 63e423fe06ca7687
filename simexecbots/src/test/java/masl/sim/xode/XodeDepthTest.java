package masl.sim.xode;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;

import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;

/**
 * Deeply nested XODE loads whatever the caller's stack (2,000 nested bodies overflowed
 * it, an internal error); past the limit it is a located error naming the limit.
 */
class XodeDepthTest {

    private static final String MASS = "<mass><mass_shape density=\"1\"><sphere radius=\"1\"/></mass_shape></mass>";

    @Test
    void twoThousandNestedBodiesLoadOnASmallStack() throws InterruptedException {
        StringBuilder bodies = new StringBuilder();
        for (int i = 0; i < 2_000; i++) {
            bodies.append("<body name=\"b").append(i).append("\">").append(MASS).append('\n');
        }
        bodies.append("</body>\n".repeat(2_000));
        AtomicReference<Object> result = new AtomicReference<>();
        Thread small = new Thread(null, () -> {
            try {
                result.set(Xode.loadSpace(bodies.toString()));
            } catch (Throwable failure) {
                result.set(failure);
            }
        }, "small stack", 512 * 1024);
        small.start();
        small.join();
        if (result.get() instanceof Throwable failure) {
            throw new AssertionError("loading failed", failure);
        }
        assertNotNull(((LoadedModel) result.get()).body("b1999"));
    }

    @Test
    void nestingPastTheLimitIsALocatedError() {
        int groups = SecureXmlReader.DEEPEST;
        String nested = "<group name=\"g\">\n".repeat(groups) + "</group>\n".repeat(groups);
        XodeException e = Xode.failure(Xode.inSpace(nested), LoadOptions.defaults());
        assertEquals(1, e.problems().size(), e::getMessage);
        // <xode>, <world> and <space> are the first three levels: the group on line 4 is the fourth.
        int line = Xode.HEADER_LINES + SecureXmlReader.DEEPEST - 3 + 1;
        assertEquals(new SourceLocation("test.xode", line, 1), e.problems().get(0).location(), e::getMessage);
        assertEquals("elements nested more than 10,000 deep: masl loads at most 10,000 levels",
                e.problems().get(0).message());
    }
}
