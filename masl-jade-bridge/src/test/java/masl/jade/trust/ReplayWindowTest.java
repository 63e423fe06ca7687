package masl.jade.trust;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** A signed control message is taken once, whatever order the numbers come in within the window. */
class ReplayWindowTest {

    private final ReplayWindow window = new ReplayWindow();

    @Test
    void eachNumberIsTakenOnce() {
        assertTrue(window.take("1"));
        assertFalse(window.take("1"), "a copy");
        assertTrue(window.take("3"));
        assertTrue(window.take("2"), "late, but new");
        assertFalse(window.take("2"));
        assertFalse(window.take("3"));
    }

    @Test
    void numbersTooFarBehindOrMissingAreRefused() {
        assertTrue(window.take(Long.toString(ReplayWindow.SIZE + 10)));
        assertFalse(window.take("10"), "left the window: it may have been taken");
        assertTrue(window.take("11"), "the oldest still remembered");
        assertFalse(window.take(null));
        assertFalse(window.take("0"));
        assertFalse(window.take("-5"));
        assertFalse(window.take("x"));
    }

    @Test
    void aLongJumpForgetsNothingItShouldRemember() {
        for (int n = 1; n <= 3 * ReplayWindow.SIZE; n++) {
            assertTrue(window.take(Integer.toString(n)), "number " + n);
        }
        for (int n = 2 * ReplayWindow.SIZE + 1; n <= 3 * ReplayWindow.SIZE; n++) {
            assertFalse(window.take(Integer.toString(n)), "number " + n + " again");
        }
        assertTrue(window.take(Long.toString(10L * ReplayWindow.SIZE)));
        assertFalse(window.take(Long.toString(3L * ReplayWindow.SIZE)), "behind the window now");
        assertTrue(window.take(Long.toString(10L * ReplayWindow.SIZE - 1)));
    }
}
