package masl.runtime.testing;

import java.util.function.BooleanSupplier;

/**
 * An agent whose {@code signal(k)} answers {@code k} once {@code condition} holds, and 0 before: a
 * program spins on it ({@code while (.signal(1) == 0) {}}, a loop the runtime does not park, for a
 * primitive is in its condition) until the test sees what MASL cannot, as another agent being done.
 */
public final class Watching extends TestAgent {

    private final BooleanSupplier condition;

    public Watching(BooleanSupplier condition) {
        this.condition = condition;
    }

    @Override
    public int signal(int value) {
        return condition.getAsBoolean() ? value : 0;
    }
}
