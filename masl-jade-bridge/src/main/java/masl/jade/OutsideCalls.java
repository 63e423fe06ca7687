package masl.jade;

import jade.lang.acl.ACLMessage;
import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import masl.jade.acl.AclInvocations;
import masl.jade.acl.JsonContent;
import masl.jade.acl.Reply;
import masl.runtime.AgentImplementation;

/**
 * Runs the primitives that FIPA agents from outside the mission invoke, each within a time limit:
 * the agent they are served for does not resume meanwhile (MASL §5 serves them on its behalf), so
 * an outsider must not hold it for as long as it likes. A primitive runs on a thread of its own; past
 * the limit it is interrupted, its late result dropped, and the requester gets {@code FAILURE}
 * {@code java.util.concurrent.TimeoutException}. The limit counts from the moment the primitive
 * starts, as the runtime's call timeout does. One mission; {@link #close} ends its threads.
 */
final class OutsideCalls implements AutoCloseable {

    /** The limit when the mission has no call timeout: long enough for a robot's move, short for a stall. */
    static final Duration DEFAULT_LIMIT = Duration.ofSeconds(10);

    private final Duration limit;
    private final ExecutorService threads = Executors.newCachedThreadPool(runnable -> {
        Thread thread = new Thread(runnable, "masl-outside-call");
        thread.setDaemon(true);
        return thread;
    });

    OutsideCalls(Duration limit) {
        this.limit = limit;
    }

    /** The answer to {@code request}: {@code call} run on {@code target} within the limit ({@link Answers#run}). */
    ACLMessage answer(ACLMessage request, PrimitiveTable.Call call, AgentImplementation target, String agent) {
        CountDownLatch started = new CountDownLatch(1);
        Future<ACLMessage> running;
        try {
            running = threads.submit(() -> {
                started.countDown();
                return Answers.run(request, call, target, null);
            });
        } catch (RejectedExecutionException missionEnded) {
            return ended(request, agent);
        }
        try {
            started.await();
            return running.get(limit.toNanos(), TimeUnit.NANOSECONDS);
        } catch (TimeoutException late) {
            running.cancel(true);
            return AclInvocations.reply(request, Reply.Kind.FAILED, JsonContent.failure(new TimeoutException(
                    call.primitive().name() + " ran past " + limit.toMillis() + " ms, the limit of a call from outside"
                            + " the mission, and was interrupted")));
        } catch (ExecutionException failed) {
            return AclInvocations.reply(request, Reply.Kind.FAILED, JsonContent.failure(failed.getCause()));
        } catch (InterruptedException stopped) {
            running.cancel(true);
            Thread.currentThread().interrupt();
            return ended(request, agent);
        }
    }

    private static ACLMessage ended(ACLMessage request, String agent) {
        return AclInvocations.reply(request, Reply.Kind.REFUSED,
                JsonContent.refusal(agent + " no longer serves: its mission has ended"));
    }

    /** Interrupts the primitives still running; their threads end. */
    @Override
    public void close() {
        threads.shutdownNow();
    }
}
