package masl.runtime.testing;

/** A subtype of {@link TestAgent} (descriptor agents/TestRobot.xml) with a static primitive. */
public class TestRobot extends TestAgent {

    /** A member of the type, not of one agent: MASL §9's {@code static}. */
    public static int census() {
        return 1;
    }
}
