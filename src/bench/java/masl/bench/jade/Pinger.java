package masl.bench.jade;

import jade.core.AID;
import jade.core.Agent;
import jade.core.behaviours.OneShotBehaviour;
import jade.lang.acl.MessageTemplate;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import masl.jade.acl.AclInvocations;

/**
 * A plain JADE agent that invokes {@code nop} on one agent with the bridge's request, waits for the
 * answer, and again, until the run's window has passed; round trips completed within the window
 * (after the warm-up) are added to the run's count. It plays from its own thread, with blocking
 * receives, as a plain JADE client does.
 */
final class Pinger extends Agent {
    private static final long serialVersionUID = 1L;

    /** How long agents may take to start, and pingers to finish beyond their window. */
    private static final Duration SLACK = Duration.ofSeconds(90);
    /** How long a measurement waits for its agents to be gone, deleted one by one ({@link masl.jade.platform.AgentDeletion}). */
    static final Duration AGENTS_GONE_WITHIN = Duration.ofSeconds(30);

    /** What all pingers of one measurement share: start signals, the count, the timing. */
    record Run(CountDownLatch started, CountDownLatch go, CountDownLatch finished, AtomicLong roundTrips,
            Duration warmUp, Duration window) {
    }

    private final transient String target;
    private final transient Run run;

    Pinger(String target, Run run) {
        this.target = target;
        this.run = run;
    }

    /** Waits for {@code latch}, failing the measurement with {@code failure} if it takes too long. */
    static void await(CountDownLatch latch, String failure) throws InterruptedException {
        if (!latch.await(SLACK.toMillis(), TimeUnit.MILLISECONDS)) {
            throw new IllegalStateException(failure);
        }
    }

    @Override
    protected void setup() {
        addBehaviour(new OneShotBehaviour(this) {
            private static final long serialVersionUID = 1L;

            @Override
            public void action() {
                try {
                    run.go().await();
                    play();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                } finally {
                    run.finished().countDown();
                }
            }
        });
        run.started().countDown();
    }

    private void play() {
        AID receiver = new AID(target, AID.ISLOCALNAME);
        long windowStart = System.nanoTime() + run.warmUp().toNanos();
        long end = windowStart + run.window().toNanos();
        long counted = 0;
        for (long sequence = 0; ; sequence++) {
            long now = System.nanoTime();
            if (now >= end) {
                break;
            }
            String replyWith = getLocalName() + "-" + sequence;
            send(AclInvocations.request(receiver, "nop", List.of(), replyWith));
            blockingReceive(MessageTemplate.MatchInReplyTo(replyWith));
            if (now >= windowStart && System.nanoTime() < end) {
                counted++;
            }
        }
        run.roundTrips().addAndGet(counted);
    }
}
