package masl.jade.acl;

import jade.core.AID;
import jade.lang.acl.ACLMessage;
import java.util.List;

/**
 * Invocations as FIPA-ACL messages (components.md, "JADE bridge"): a {@code REQUEST} in language
 * {@value #LANGUAGE}, ontology {@value #ONTOLOGY}, with {@link JsonContent} and a fresh
 * {@code reply-with}; answered by {@code INFORM}, {@code REFUSE}, {@code FAILURE} or
 * {@code NOT_UNDERSTOOD} with {@code in-reply-to} set to it.
 *
 * <p>A plain FIPA agent may leave language and ontology out; when given they must be these.
 */
public final class AclInvocations {

    public static final String LANGUAGE = "json";
    public static final String ONTOLOGY = "masl";

    private AclInvocations() {
    }

    /** A request to {@code receiver} to invoke {@code primitive} with {@code args}. */
    public static ACLMessage request(AID receiver, String primitive, List<?> args, String replyWith) {
        ACLMessage request = new ACLMessage(ACLMessage.REQUEST);
        request.addReceiver(receiver);
        request.setLanguage(LANGUAGE);
        request.setOntology(ONTOLOGY);
        request.setReplyWith(replyWith);
        request.setContent(JsonContent.request(primitive, args));
        return request;
    }

    /**
     * Reads an invocation request.
     *
     * @throws ContentException if it is not a {@code REQUEST} in this language and ontology, or its
     *                          content is not a request ({@link JsonContent#parseRequest})
     */
    public static InvocationRequest readRequest(ACLMessage message) throws ContentException {
        if (message.getPerformative() != ACLMessage.REQUEST) {
            throw new ContentException("performative " + ACLMessage.getPerformative(message.getPerformative())
                    + " is not understood: a MASL agent answers REQUEST (invocations),"
                    + " QUERY_REF (attributes), SUBSCRIBE and CANCEL (events) and INFORM masl-event");
        }
        if (message.getLanguage() != null && !LANGUAGE.equals(message.getLanguage())) {
            throw new ContentException("language \"" + message.getLanguage() + "\" is not understood: use \""
                    + LANGUAGE + "\"");
        }
        if (message.getOntology() != null && !ONTOLOGY.equals(message.getOntology())) {
            throw new ContentException("ontology \"" + message.getOntology() + "\" is not understood: use \""
                    + ONTOLOGY + "\"");
        }
        return JsonContent.parseRequest(message.getContent());
    }

    /** The answer to {@code request}: its receivers, conversation and {@code in-reply-to} set by JADE. */
    public static ACLMessage reply(ACLMessage request, Reply.Kind kind, String content) {
        ACLMessage reply = request.createReply();
        reply.setPerformative(performative(kind));
        reply.setLanguage(LANGUAGE);
        reply.setOntology(ONTOLOGY);
        reply.setContent(content);
        return reply;
    }

    /** The {@code NOT_UNDERSTOOD} answering {@code request}, with the problem as its reason. */
    public static ACLMessage notUnderstood(ACLMessage request, ContentException problem) {
        return reply(request, Reply.Kind.NOT_UNDERSTOOD, JsonContent.notUnderstood(problem));
    }

    /**
     * Reads the answer to a request.
     *
     * @throws ContentException if its performative is none of the four answers, or its content is
     *                          not the answer its performative says
     */
    public static Reply readReply(ACLMessage reply) throws ContentException {
        Reply.Kind kind = switch (reply.getPerformative()) {
            case ACLMessage.INFORM -> Reply.Kind.RESULT;
            case ACLMessage.REFUSE -> Reply.Kind.REFUSED;
            case ACLMessage.FAILURE -> Reply.Kind.FAILED;
            case ACLMessage.NOT_UNDERSTOOD -> Reply.Kind.NOT_UNDERSTOOD;
            default -> throw new ContentException("performative "
                    + ACLMessage.getPerformative(reply.getPerformative()) + " does not answer an invocation");
        };
        return JsonContent.parseReply(kind, reply.getContent());
    }

    private static int performative(Reply.Kind kind) {
        return switch (kind) {
            case RESULT -> ACLMessage.INFORM;
            case REFUSED -> ACLMessage.REFUSE;
            case FAILED -> ACLMessage.FAILURE;
            case NOT_UNDERSTOOD -> ACLMessage.NOT_UNDERSTOOD;
        };
    }
}
