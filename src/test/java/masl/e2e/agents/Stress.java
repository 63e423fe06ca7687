package masl.e2e.agents;

import masl.agents.Default;

/**
 * An agent of the stress test: {@code timeUp()} says whether the deadline has passed, a
 * {@link System#nanoTime()} the test puts in the system property {@value #DEADLINE} before it creates
 * the agents.
 */
public class Stress extends Default {

    public static final String DEADLINE = "masl.stress.deadline";

    private final long deadline = Long.parseLong(System.getProperty(DEADLINE, "0"));

    public boolean timeUp() {
        return System.nanoTime() - deadline >= 0;
    }
}
