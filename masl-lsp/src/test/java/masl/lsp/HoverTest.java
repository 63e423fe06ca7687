package masl.lsp;

import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** Hover: what a primitive, an attribute, a block and a declared name are, in the editor's words. */
class HoverTest {

    private final Editor editor = new Editor();

    @AfterEach
    void close() {
        editor.close();
    }

    private String hoverOn(String typed) {
        editor.open(Programs.team(typed));
        String text = editor.hover();
        assertTrue(text != null, "no hover at " + typed);
        return text;
    }

    private static void assertContains(String expected, String text) {
        assertTrue(text.contains(expected), "expected «" + expected + "» in:\n" + text);
    }

    @Test
    void anAsynchronousPrimitiveWithItsCountermeasureAndExceptions() {
        String text = hoverOn("r1.calib‸rate();");
        assertContains("boolean calibrate()", text);
        assertContains("**asynchronous**", text);
        assertContains("Countermeasure: `abortCalibration`", text);
        assertContains("Throws `masl.agents.BatteryEmptyException`", text);
    }

    @Test
    void whichStatesLetUserGroupAndOtherCallAPrimitive() {
        String text = hoverOn(".moveFor‸ward(1.0);");
        assertContains("double moveForward(double distance)", text);
        assertContains("**synchronous**", text);
        assertContains("- *user (the agent itself)*: default, degraded\n", text);
        assertContains("- *group (an agent in the same innermost block)*: default\n", text);
        assertContains("- *other*: default\n", text);
    }

    @Test
    void anAccessorAndAPrimitiveOfSeveralTypes() {
        String text = hoverOn("total = .getProx‸yID();");
        assertContains("int getProxyID()", text);
        assertContains("accessor (zero duration", text);
        assertContains("Primitive of Default, Rover", text);
    }

    @Test
    void anAttributeWithWhoMayReadIt() {
        String text = hoverOn("total = r1.MOVE_C‸OST;");
        assertContains("static final int MOVE_COST = 5", text);
        assertContains("Who may read it", text);
        assertContains("- *other*: default, degraded, dead\n", text);
    }

    @Test
    void aBlocksModeAndTest() {
        String text = hoverOn("break(wo‸rk);");
        assertContains("asynchronous entry work (.getProxyID() > 0)", text);
        assertContains("Mode: **asynchronous**", text);
        assertContains("Test: `.getProxyID() > 0`; inside `main`", text);
    }

    @Test
    void anEntryMemberAndItsBlock() {
        String text = hoverOn("total = work.getActive‸Count();");
        assertContains("int getActiveCount()", text);
        assertContains("Entry member of `work`", text);
        assertContains("Mode: **asynchronous**", text);
    }

    @Test
    void aVariableAnEventAndAnAgent() {
        assertContains("shared int total", hoverOn("tot‸al++;"));
        assertContains("Declared in block `main`", hoverOn("tot‸al++;"));
        assertContains("local event done", hoverOn("emit(do‸ne);"));
        assertContains("Rover r1", hoverOn("r‸1.stop();"));
    }

    @Test
    void anAgentTypeAndItsDescriptor() {
        editor.open(Programs.TEAM.replace("Rover r1", "Ro‸ver r1"));
        String text = editor.hover();
        assertContains("agent type Rover", text);
        assertContains("implemented by `masl.agents.SoftWheeledRobot`, extends `Robot`", text);
    }

    @Test
    void nothingOnAKeywordOrAnUnknownName() {
        editor.open(Programs.team("whi‸le (true) {}"));
        assertNull(editor.hover());
        editor.open(Programs.team("nowh‸ere++;"));
        assertNull(editor.hover());
    }
}
