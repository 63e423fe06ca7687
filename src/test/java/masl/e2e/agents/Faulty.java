package masl.e2e.agents;

import java.util.concurrent.CountDownLatch;
import masl.agents.Default;

/** An agent whose primitives misbehave on purpose: {@code hang()} returns only when interrupted, {@code fail()} throws. */
public class Faulty extends Default {

    public int hang() throws InterruptedException {
        new CountDownLatch(1).await();
        return 42;
    }

    public int fail() {
        throw new IllegalStateException("fail() always fails");
    }
}
