package masl.e2e.agents;

import java.util.concurrent.CountDownLatch;
import masl.agents.Default;

/**
 * The end-to-end tests' agent type (workers/Worker.xml): a battery drained by a primitive, a
 * static counter, a constant, synchronous and asynchronous primitives, an asynchronous one held
 * by a latch until a test program opens it, and one with a countermeasure.
 */
public class Worker extends Default {

    public static final int LIMIT = 50;
    public static int made;

    public int battery = 100;

    private final CountDownLatch gate = new CountDownLatch(1);

    /** Synchronous: lowers the battery by {@code amount} and gives what is left. */
    public int drain(int amount) {
        battery -= amount;
        return battery;
    }

    /** Synchronous: twice {@code value}. */
    public int twice(int value) {
        return 2 * value;
    }

    /** Asynchronous: ten times {@code value}, once {@link #open} opened this agent's gate. */
    public int slow(int value) throws InterruptedException {
        gate.await();
        return 10 * value;
    }

    /** Synchronous: opens {@code worker}'s gate; it does not wait, so no scheduler thread is held. */
    public void open(Worker worker) {
        worker.gate.countDown();
    }

    /** Asynchronous, with the countermeasure {@link #stopCalibrate}. */
    public void calibrate() {
        made++;
    }

    /** Undoes {@link #calibrate}: logs it. */
    public void stopCalibrate() {
        logln(getProxyID() + " stop");
    }
}
