package masl.runtime.testing;

import java.util.concurrent.CountDownLatch;
import masl.runtime.AgentImplementation;

/** The primitives of {@code Default} the tests need (masl-runtime cannot depend on the agents module). */
public class TestAgent extends AgentImplementation {

    /** An attribute for the permeability tests (descriptor agents/Default.xml). */
    public volatile int battery;

    private final PhaseLog phases;

    public TestAgent() {
        this(null);
    }

    /** An agent whose {@link #instruction}s go to {@code phases}. */
    public TestAgent(PhaseLog phases) {
        this.phases = phases;
    }

    public int getProxyID() {
        return services().proxyId();
    }

    public void nop() {
        // One instruction of non-zero duration and nothing else.
    }

    public void log(String message) {
        services().log(message);
    }

    public void logln(String message) {
        services().log(message + "\n");
    }

    /**
     * One instruction, recorded with this agent's proxy id in the test's {@link PhaseLog}; returns
     * {@code label}, so that an instruction that does something else records it too
     * ({@code emitWithMessage(e, .instruction("i2"))}).
     */
    public String instruction(String label) {
        phases.instruction(getProxyID(), label);
        return label;
    }

    /** Logs {@code label} and {@code value} on a line and returns {@code value}: an expression a test sees evaluated. */
    public int logged(String label, int value) {
        logln(label + value);
        return value;
    }

    /** Uses {@code amount} of the battery and returns what is left (the degraded-mode tests). */
    public int drain(int amount) {
        battery -= amount;
        return battery;
    }

    /** An asynchronous primitive (labels, §10): logs that it measures and gives 10 times the proxy id. */
    public int measure() {
        logln(getProxyID() + " measures");
        return 10 * getProxyID();
    }

    /** An asynchronous primitive with the countermeasure {@link #stopCalibrate} (§9): logs that it calibrates. */
    public int calibrate() {
        logln(getProxyID() + " calibrates");
        return 1;
    }

    /** {@link #calibrate}'s countermeasure: logs that it stops. */
    public void stopCalibrate() {
        logln(getProxyID() + " stops");
    }

    /**
     * A hook for a test's agent (opening a latch, taking a time); gives {@code value} back. An
     * accessor, of zero duration (§5): no step boundary stands between it and the next statement.
     */
    public int signal(int value) {
        return value;
    }

    /** Throws {@link ArithmeticException} for a zero divisor: a primitive's exception (§9). */
    public int divide(int dividend, int divisor) {
        return dividend / divisor;
    }

    /** A primitive that never returns by itself: it waits until its thread is interrupted, then gives 42. */
    public int hang() {
        awaitOpening(new CountDownLatch(1));
        return 42;
    }

    /**
     * Waits in a primitive until {@code latch} opens, or until the primitive's thread is interrupted
     * (a call timed out, the mission stopped): then it returns, the interrupt kept.
     */
    protected static void awaitOpening(CountDownLatch latch) {
        try {
            latch.await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
