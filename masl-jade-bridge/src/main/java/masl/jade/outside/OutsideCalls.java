package masl.jade.outside;

import jade.lang.acl.ACLMessage;
import java.time.Duration;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicInteger;
import masl.jade.Answers;
import masl.jade.PrimitiveTable;
import masl.jade.acl.AclInvocations;
import masl.jade.acl.JsonContent;
import masl.jade.acl.Reply;
import masl.runtime.AgentImplementation;

/**
 * Runs the primitives that FIPA agents from outside the mission invoke, each within a time limit:
 * the agent they are served for does not resume meanwhile (MASL §5 serves them on its behalf), so
 * an outsider must not hold it for as long as it likes. A primitive runs on the thread that serves
 * it; a watchdog interrupts it once past the limit, its late result is dropped, and the requester
 * gets {@code FAILURE} {@code java.util.concurrent.TimeoutException}. The limit counts from the
 * moment the primitive starts, as the runtime's call timeout does. One mission; {@link #close} ends
 * the watchdog and interrupts the primitives still running, whose requesters are refused.
 *
 * <p>On the serving thread, not handed to a thread of its own: the hand-over and the wake-up back
 * cost two thread switches per request, which made the bridge's round trip 1.5× raw JADE's.
 * The price: a primitive that ignores interruption holds the agent until it
 * returns; its requester is then answered the same {@code TimeoutException}.
 *
 * <p>Public for {@link masl.jade.JadeLauncher} and {@code MaslJadeAgent}, and for the
 * coordinator serving the requests bodies relay ({@code placement}).
 */
public final class OutsideCalls implements AutoCloseable {

    /** The limit when the mission has no call timeout: long enough for a robot's move, short for a stall. */
    public static final Duration DEFAULT_LIMIT = Duration.ofSeconds(10);
    /** The watchdog looks at the running primitives this often at most: a tenth of the limit, 1 to 100 ms. */
    private static final long MAX_WATCH_PERIOD_MILLIS = 100;

    private final Duration limit;
    private final Set<Running> running = ConcurrentHashMap.newKeySet();
    private final ScheduledExecutorService watchdog = Executors.newSingleThreadScheduledExecutor(runnable -> {
        Thread thread = new Thread(runnable, "masl-outside-calls-watchdog");
        thread.setDaemon(true);
        return thread;
    });
    private volatile boolean closed;

    public OutsideCalls(Duration limit) {
        this.limit = limit;
        long period = Math.max(1, Math.min(limit.toMillis() / 10, MAX_WATCH_PERIOD_MILLIS));
        watchdog.scheduleAtFixedRate(this::interruptLate, period, period, TimeUnit.MILLISECONDS);
    }

    /**
     * The answer to {@code request}: {@code call} run on {@code target} ({@link Answers#run}), on this
     * thread, within the limit.
     */
    public ACLMessage answer(ACLMessage request, PrimitiveTable.Call call, AgentImplementation target, String agent) {
        Running primitive = new Running(Thread.currentThread(), System.nanoTime() + limit.toNanos());
        running.add(primitive);
        ACLMessage answer;
        try {
            // Checked once registered, so that close() either sees this call or this call sees it closed.
            if (closed) {
                primitive.interrupt(Running.ENDED);
            }
            answer = primitive.state() == Running.RUNNING ? Answers.run(request, call, target, null) : null;
        } finally {
            running.remove(primitive);
        }
        return switch (primitive.finish()) {
            case Running.FINISHED -> answer;
            case Running.LATE -> AclInvocations.reply(request, Reply.Kind.FAILED, JsonContent.failure(
                    new TimeoutException(call.primitive().name() + " ran past " + limit.toMillis() + " ms, the limit"
                            + " of a call from outside the mission, and was interrupted")));
            default -> AclInvocations.reply(request, Reply.Kind.REFUSED,
                    JsonContent.refusal(agent + " no longer serves: its mission has ended"));
        };
    }

    private void interruptLate() {
        long now = System.nanoTime();
        for (Running primitive : running) {
            if (now - primitive.deadline >= 0) {
                primitive.interrupt(Running.LATE);
            }
        }
    }

    /** Ends the watchdog and interrupts the primitives still running: their requesters are refused. */
    @Override
    public void close() {
        closed = true;
        watchdog.shutdownNow();
        running.forEach(primitive -> primitive.interrupt(Running.ENDED));
    }

    /**
     * One primitive running on its serving thread. It ends {@link #FINISHED} (by that thread, in
     * time) or is interrupted once, {@link #LATE} or {@link #ENDED} (by the watchdog or
     * {@link #close}); the interrupt is meant for the primitive, and is cleared from the thread when it
     * returns.
     */
    private static final class Running {
        static final int RUNNING = 0;
        static final int FINISHED = 1;
        static final int INTERRUPTING = 2;
        static final int LATE = 3;
        static final int ENDED = 4;

        final Thread thread;
        final long deadline;
        private final AtomicInteger state = new AtomicInteger(RUNNING);

        Running(Thread thread, long deadline) {
            this.thread = thread;
            this.deadline = deadline;
        }

        int state() {
            return state.get();
        }

        /** Interrupts the primitive, once, for {@code why}: {@link #LATE} or {@link #ENDED}. */
        void interrupt(int why) {
            if (state.compareAndSet(RUNNING, INTERRUPTING)) {
                thread.interrupt();
                state.set(why);
            }
        }

        /** By the serving thread once the primitive returned: how it ended, the thread's interrupt for it cleared. */
        int finish() {
            if (state.compareAndSet(RUNNING, FINISHED)) {
                return FINISHED;
            }
            while (state.get() == INTERRUPTING) {
                Thread.onSpinWait();
            }
            Thread.interrupted();
            return state.get();
        }
    }
}
