package masl.jade.trust;

import jade.core.AID;
import jade.lang.acl.ACLMessage;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Function;

/**
 * The coordinator's requests waiting for their answers. A request gets an unguessable
 * {@code reply-with} ({@link UnguessableIds}); an answer is taken only with that {@code in-reply-to}
 * and from the agent the request went to, or, for an undeliverable request, from the platform's
 * AMS. Anything else (a guess, a replay to another request, an answer from a third agent) is no
 * answer. Thread-safe.
 *
 * <p>Public for the coordinator ({@code placement}) and the hosts of external agents ({@code
 * external}), which take answers only through it: the trust checks live in this package alone.
 */
public final class PendingAnswers {

    private final String prefix;
    private final Map<String, Pending> pending = new ConcurrentHashMap<>();

    private record Pending(AID receiver, CompletableFuture<ACLMessage> answer) {
    }

    /** What {@link #classify} made of a message. */
    public enum Taken { ANSWER, UNDELIVERABLE, NONE }

    public PendingAnswers(String prefix) {
        this.prefix = prefix;
    }

    /** Sets {@code request}'s {@code reply-with} and returns the future its answer completes. */
    public CompletableFuture<ACLMessage> register(ACLMessage request) {
        String replyWith = UnguessableIds.next(prefix);
        request.setReplyWith(replyWith);
        CompletableFuture<ACLMessage> answer = new CompletableFuture<>();
        pending.put(replyWith, new Pending((AID) request.getAllReceiver().next(), answer));
        return answer;
    }

    /**
     * What {@code message} is: {@link Taken#ANSWER} to a waiting request, from that request's
     * receiver; {@link Taken#UNDELIVERABLE}, a {@code FAILURE} from {@code ams} for a waiting request
     * (its receiver's container is gone); {@link Taken#NONE}, anything else, which must complete nothing.
     */
    public Taken classify(ACLMessage message, AID ams) {
        String inReplyTo = message.getInReplyTo();
        Pending waiting = inReplyTo == null ? null : pending.get(inReplyTo);
        if (waiting == null || message.getSender() == null) {
            return Taken.NONE;
        }
        if (message.getSender().equals(waiting.receiver())) {
            return Taken.ANSWER;
        }
        return message.getPerformative() == ACLMessage.FAILURE && message.getSender().equals(ams) ? Taken.UNDELIVERABLE
                : Taken.NONE;
    }

    /** Completes the request {@code message} answers with it, if it still waits ({@link #classify} first). */
    public void complete(ACLMessage message) {
        Pending waiting = pending.remove(message.getInReplyTo());
        if (waiting != null) {
            waiting.answer().complete(message);
        }
    }

    /** The receiver of the request {@code message} answers; null if it answers none. */
    public AID receiverOf(ACLMessage message) {
        Pending waiting = message.getInReplyTo() == null ? null : pending.get(message.getInReplyTo());
        return waiting == null ? null : waiting.receiver();
    }

    /** Fails, with {@code why}, the request with {@code reply-with} {@code replyWith} if it still waits. */
    public void fail(String replyWith, Throwable why) {
        Pending waiting = pending.remove(replyWith);
        if (waiting != null) {
            waiting.answer().completeExceptionally(why);
        }
    }

    /** Fails every request to one of {@code receivers} (local names) with the exception made of its reason. */
    public void failAll(Map<String, String> reasonByReceiver, Function<String, ? extends Throwable> exception) {
        pending.forEach((replyWith, waiting) -> {
            String reason = reasonByReceiver.get(waiting.receiver().getLocalName());
            if (reason != null && pending.remove(replyWith, waiting)) {
                waiting.answer().completeExceptionally(exception.apply(reason));
            }
        });
    }

    /** Fails every waiting request with {@code why}. */
    public void failEvery(Throwable why) {
        pending.keySet().forEach(replyWith -> fail(replyWith, why));
    }
}
