package masl.jade.deployment;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;

/**
 * One side's messages on the link between the mission and a container, combined: they go as one
 * {@link Batch}, in the order added, when no agent of the link is <em>busy</em> on this side
 * any more: on the mission's side, when no agent of the container waits for an answer, a wake-up or
 * a resumption the mission has not given yet; on the container's side, when none of its agents is
 * running a step there. In a lock-step mission the barrier's trip wakes every agent of a container,
 * and their wake-ups go as one message; their arrivals at the next barrier come back as one.
 *
 * <p>An agent that stays busy (a long primitive, a request the mission holds: a synchronous call, a
 * wait for a state) must not hold back the others: what is held goes anyway once nothing was added
 * for {@link #QUIET_NANOS} (looked at every {@link #QUIET_NANOS}, so between one and two of them
 * after the last message, which is added with no clock read), or {@link #HOLD_NANOS} after the first
 * message held. A message the other side waits for while this side is busy (a call to run, its
 * result) goes at once ({@link #now}).
 */
final class Outbox {

    /**
     * How long the outbox waits for more messages once none is added: the agents of a wave come close
     * together, but on a loaded machine a thread waits a scheduler's time slice or two to run.
     */
    static final long QUIET_NANOS = TimeUnit.MILLISECONDS.toNanos(10);
    /**
     * The longest a message is held. Rarely reached: an agent waiting for its answer adds nothing
     * more, so the messages held stop growing, and go, once each agent has sent its own.
     */
    static final long HOLD_NANOS = TimeUnit.MILLISECONDS.toNanos(200);

    /**
     * One thread of the JVM times every outbox's held messages; it ends a second after its last
     * timing, so that no thread of masl's outlives the missions of a JVM that goes on (a library
     * user's, a serving container's between missions).
     */
    private static final ScheduledExecutorService TIMER = timer();

    private final Wire wire;
    private int busy;
    private List<Batch.Held> held;
    private long firstHeld;
    /** Whether a message was added since the timer last looked: what tells it quiet, with no clock read per message. */
    private boolean addedSinceLook;
    private boolean timed;

    private static ScheduledExecutorService timer() {
        ScheduledThreadPoolExecutor timer = new ScheduledThreadPoolExecutor(1, work -> {
            Thread thread = new Thread(work, "masl-deployed-outbox");
            thread.setDaemon(true);
            return thread;
        });
        timer.setKeepAliveTime(1, TimeUnit.SECONDS);
        timer.allowCoreThreadTimeOut(true);
        return timer;
    }

    /** @param busy how many agents of the link are busy on this side to begin with */
    Outbox(Wire wire, int busy) {
        this.wire = wire;
        this.busy = busy;
    }

    /**
     * Adds {@code message}, and {@code busyChange} to the agents busy on this side (-1: it unblocks
     * one there); the outbox owns {@code message} from then on.
     */
    void add(ObjectNode message, int busyChange) {
        add(Batch.Held.of(message), busyChange);
    }

    /** Adds {@code message} as {@link #add(ObjectNode, int)} does; its fields must not change until it is sent. */
    synchronized void add(Batch.Held message, int busyChange) {
        if (held == null) {
            held = new ArrayList<>();
            firstHeld = System.nanoTime();
        }
        held.add(message);
        addedSinceLook = true;
        busy(busyChange);
        if (held != null && !timed) {
            timed = true;
            addedSinceLook = false;
            TIMER.schedule(this::expire, QUIET_NANOS, TimeUnit.NANOSECONDS);
        }
    }

    /** Sends {@code message} at once, after what is held; the outbox owns it from then on. */
    synchronized void now(ObjectNode message) {
        add(message, 0);
        if (held != null) {
            flush();
        }
    }

    /** {@code change} more agents are busy on this side (fewer if negative); none left sends what is held. */
    synchronized void busy(int change) {
        busy += change;
        if (busy <= 0 && held != null) {
            flush();
        }
    }

    private synchronized void expire() {
        timed = false;
        if (held == null) {
            return;
        }
        // Quiet: nothing was added since the last look, QUIET_NANOS ago (or up to twice that since the last message).
        boolean quiet = !addedSinceLook;
        long holdLeft = HOLD_NANOS - (System.nanoTime() - firstHeld);
        if (quiet || holdLeft <= 0) {
            flush();
        } else {
            timed = true;
            addedSinceLook = false;
            TIMER.schedule(this::expire, Math.min(QUIET_NANOS, holdLeft), TimeUnit.NANOSECONDS);
        }
    }

    private void flush() {
        ObjectNode batch = Batch.of(held);
        held = null;
        wire.send(batch);
    }
}
