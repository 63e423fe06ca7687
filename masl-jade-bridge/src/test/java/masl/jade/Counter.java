package masl.jade;

import masl.runtime.testing.TestAgent;

/** An agent type with state: a primitive that counts and an attribute others may read and write. */
public class Counter extends TestAgent {

    /** What {@link #count} has counted, or what another agent wrote. */
    public int total;

    /** Adds {@code by} to the total and gives the total; a negative {@code by} throws. */
    public int count(int by) {
        if (by < 0) {
            throw new IllegalArgumentException("a count goes up");
        }
        total += by;
        return total;
    }

    /** {@link #count}, as an asynchronous primitive: launched, it runs on a thread of its own. */
    public int countAside(int by) {
        return count(by);
    }
}
