package masl.e2e.agents;

import java.util.concurrent.CountDownLatch;
import masl.agents.Default;

/** An agent whose primitives misbehave on purpose: {@code hang()} never returns by itself, {@code fail()} throws. */
public class Faulty extends Default {

    /** Opened when a test is over, so that hung primitives' threads end. */
    public static final CountDownLatch RELEASE_HUNG = new CountDownLatch(1);

    public int hang() throws InterruptedException {
        RELEASE_HUNG.await();
        return 42;
    }

    public int fail() {
        throw new IllegalStateException("fail() always fails");
    }
}
