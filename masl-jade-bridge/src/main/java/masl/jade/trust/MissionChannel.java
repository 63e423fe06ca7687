package masl.jade.trust;

import jade.core.AID;
import jade.lang.acl.ACLMessage;
import java.io.IOException;
import java.util.HashMap;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;

/**
 * One party's end of the authenticated messages of a mission spanning containers: the coordinator,
 * a container's agent and each body have one, under their own (local) name. Every message between
 * parties, whatever its kind (control, request, answer, relay, event), is signed here ({@link
 * MissionSecret}: sender, receiver, sequence number, conversation, ids and content) and checked
 * here before its receiver acts on it; a sender number is taken once per sender ({@link
 * ReplayWindow}). JADE lets any agent of the platform write any sender and see others' messages:
 * only a signature tells a party from an agent that merely names itself one. Thread-safe.
 *
 * <p>Public for the parties of a mission spanning containers ({@code placement}): the trust checks
 * live in this package alone.
 */
public final class MissionChannel {

    private final String self;
    private final MissionSecret.Source source;
    /** The secret once known: given, or read from the source and confirmed by a message bearing its signature. */
    private volatile MissionSecret secret;
    private final Map<String, AtomicLong> sequences = new ConcurrentHashMap<>();
    private final Map<String, ReplayWindow> taken = new HashMap<>();

    private MissionChannel(String self, MissionSecret secret, MissionSecret.Source source) {
        this.self = self;
        this.secret = secret;
        this.source = source;
    }

    /** The end of party {@code self}, which knows the mission's secret. */
    public static MissionChannel of(String self, MissionSecret secret) {
        return new MissionChannel(self, secret, MissionSecret.Source.of(secret));
    }

    /**
     * The end of party {@code self} (a container), which reads the secret from {@code source} when a
     * message comes, until one bears its signature: the coordinator may write it after the container started.
     */
    public static MissionChannel reading(String self, MissionSecret.Source source) {
        return new MissionChannel(self, null, source);
    }

    /** The mission's secret, once a message has confirmed it (or it was given); null before. */
    public MissionSecret secret() {
        return secret;
    }

    /**
     * Signs {@code message} (one receiver) as this party's next message to that receiver, and sets
     * this party as its sender.
     *
     * @throws IllegalStateException if the secret is not known yet (no message confirmed it)
     */
    public ACLMessage sign(ACLMessage message, AID sender) {
        MissionSecret known = secret;
        if (known == null) {
            throw new IllegalStateException(self + " signs nothing before a message of its mission confirmed the secret");
        }
        String receiver = ((AID) message.getAllReceiver().next()).getLocalName();
        known.sign(message, self, receiver,
                sequences.computeIfAbsent(receiver, r -> new AtomicLong()).incrementAndGet());
        message.setSender(sender);
        return message;
    }

    /**
     * Why this party must not act on {@code message}: no sender, not signed with the mission's
     * secret by the sender it names for this party, or a copy of one already taken; null if it may
     * (the message's number is then taken).
     */
    public String refusal(ACLMessage message) {
        if (message.getSender() == null) {
            return "it names no sender";
        }
        String sender = message.getSender().getLocalName();
        MissionSecret candidate = secret;
        if (candidate == null) {
            try {
                candidate = source.get();
            } catch (IOException unreadable) {
                return "cannot read the mission's secret: " + unreadable.getMessage();
            }
        }
        if (!candidate.signed(message, sender, self)) {
            return "not signed with the mission's secret";
        }
        secret = candidate;
        synchronized (taken) {
            return taken.computeIfAbsent(sender, s -> new ReplayWindow())
                    .take(message.getUserDefinedParameter(MissionSecret.SEQUENCE)) ? null
                    : "a copy of a message already taken";
        }
    }
}
