package masl.jade.acl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import jade.core.AID;
import jade.lang.acl.ACLMessage;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The FIPA-ACL envelope of invocations: performatives, language, ontology, reply-with/in-reply-to. */
class AclInvocationsTest {

    private static final AID CALLEE = new AID("b@test", AID.ISGUID);

    @Test
    void aRequestAndItsRepliesCarryTheConversation() throws Exception {
        ACLMessage request = AclInvocations.request(CALLEE, "log", List.of("hi"), "r-1");
        request.setSender(new AID("caller@test", AID.ISGUID));
        assertEquals(ACLMessage.REQUEST, request.getPerformative());
        assertEquals("json", request.getLanguage());
        assertEquals("masl", request.getOntology());
        InvocationRequest read = AclInvocations.readRequest(request);
        assertEquals("log", read.primitive());
        assertEquals(List.of("\"hi\""), read.args().stream().map(argument -> argument.value().toString()).toList());

        ACLMessage inform = AclInvocations.reply(request, Reply.Kind.RESULT, JsonContent.result(null));
        assertEquals(ACLMessage.INFORM, inform.getPerformative());
        assertEquals("r-1", inform.getInReplyTo());
        assertEquals(List.of(new AID("caller@test", AID.ISGUID)), receivers(inform));
        assertEquals(Reply.Result.class, AclInvocations.readReply(inform).getClass());

        assertEquals(ACLMessage.REFUSE, AclInvocations.reply(request, Reply.Kind.REFUSED, "{}").getPerformative());
        assertEquals(ACLMessage.FAILURE, AclInvocations.reply(request, Reply.Kind.FAILED, "{}").getPerformative());
        ACLMessage notUnderstood = AclInvocations.notUnderstood(request, new ContentException("no"));
        assertEquals(ACLMessage.NOT_UNDERSTOOD, notUnderstood.getPerformative());
        assertEquals(new Reply.NotUnderstood("message: error: no"), AclInvocations.readReply(notUnderstood));
    }

    @Test
    void aPlainFipaRequestWithoutLanguageOrOntologyIsUnderstood() throws Exception {
        ACLMessage request = new ACLMessage(ACLMessage.REQUEST);
        request.setContent("{\"primitive\":\"nop\"}");
        assertEquals(new InvocationRequest("nop", 1, 14, List.of()), AclInvocations.readRequest(request));
    }

    @Test
    void otherPerformativesLanguagesAndOntologiesAreNotUnderstood() {
        ACLMessage propose = AclInvocations.request(CALLEE, "nop", List.of(), "r");
        propose.setPerformative(ACLMessage.PROPOSE);
        assertEquals("message: error: performative PROPOSE is not understood: a MASL agent answers REQUEST"
                + " (invocations), QUERY_REF (attributes), SUBSCRIBE and CANCEL (events) and INFORM masl-event",
                assertThrows(ContentException.class, () -> AclInvocations.readRequest(propose)).describe());
        ACLMessage sl = AclInvocations.request(CALLEE, "nop", List.of(), "r");
        sl.setLanguage("fipa-sl");
        assertEquals("message: error: language \"fipa-sl\" is not understood: use \"json\"",
                assertThrows(ContentException.class, () -> AclInvocations.readRequest(sl)).describe());
        ACLMessage other = AclInvocations.request(CALLEE, "nop", List.of(), "r");
        other.setOntology("robots");
        assertEquals("message: error: ontology \"robots\" is not understood: use \"masl\"",
                assertThrows(ContentException.class, () -> AclInvocations.readRequest(other)).describe());
    }

    @Test
    void aMessageThatAnswersNoInvocationIsRejected() {
        ACLMessage agree = new ACLMessage(ACLMessage.AGREE);
        assertEquals("message: error: performative AGREE does not answer an invocation",
                assertThrows(ContentException.class, () -> AclInvocations.readReply(agree)).describe());
    }

    private static List<AID> receivers(ACLMessage message) {
        List<AID> receivers = new ArrayList<>();
        for (Iterator<?> all = message.getAllReceiver(); all.hasNext(); ) {
            receivers.add((AID) all.next());
        }
        return receivers;
    }
}
