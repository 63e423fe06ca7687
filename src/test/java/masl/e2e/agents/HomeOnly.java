package masl.e2e.agents;

import masl.agents.Default;

/**
 * An agent whose class cannot be initialised in a JVM whose environment has {@value #NO_ROBOT}: as a
 * driver whose hardware is missing on some host. The coordinator's JVM makes it; a container started
 * with the variable cannot host it.
 */
public class HomeOnly extends Default {

    public static final String NO_ROBOT = "MASL_TEST_NO_ROBOT";

    static {
        if (System.getenv(NO_ROBOT) != null) {
            throw new IllegalStateException("no robot on this host");
        }
    }
}
