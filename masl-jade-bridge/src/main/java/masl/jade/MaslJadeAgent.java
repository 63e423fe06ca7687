package masl.jade;

import jade.core.Agent;
import jade.core.behaviours.Behaviour;
import jade.core.behaviours.CyclicBehaviour;
import jade.domain.DFService;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.domain.FIPAAgentManagement.Property;
import jade.domain.FIPAAgentManagement.ServiceDescription;
import jade.domain.FIPAException;
import jade.lang.acl.ACLMessage;
import java.lang.reflect.InvocationTargetException;
import java.util.concurrent.CountDownLatch;
import masl.jade.acl.AclInvocations;
import masl.jade.acl.ContentException;
import masl.jade.acl.JsonContent;
import masl.jade.acl.Reply;
import masl.runtime.AgentImplementation;
import masl.runtime.Mission;
import masl.runtime.descriptor.Primitive;

/**
 * The JADE agent of one MASL agent, named after it. It registers with the DF (service
 * {@value #TYPE_SERVICE} named after its type, and one service {@value #PRIMITIVE_SERVICE} per
 * primitive), answers invocation requests from any FIPA agent, and hosts the threaded behaviour
 * in which the MASL agent's program runs ({@link ThreadedBehaviourScheduler}).
 *
 * <p>A request is read on this agent's JADE thread: one that is malformed, names an unknown
 * primitive or gives unusable arguments is answered {@code NOT_UNDERSTOOD} at once. A valid one is
 * queued at the MASL agent ({@link Mission#submitInvocation}) and served as MASL §5 says, on the
 * program's thread: {@code REFUSE} if the agent's permeability state then denies it to an
 * <em>other</em>, else the primitive runs and
 * the answer is {@code INFORM} with its result or {@code FAILURE} with what it threw.
 */
final class MaslJadeAgent extends Agent {
    private static final long serialVersionUID = 1L;

    /** DF service type of a MASL agent's type; the service's name is the type's short name. */
    static final String TYPE_SERVICE = "masl-agent";
    /** DF service type of each primitive; the service's name is the primitive's name. */
    static final String PRIMITIVE_SERVICE = "masl-primitive";

    private final transient int proxyId;
    private final transient AgentImplementation implementation;
    private final transient PrimitiveTable primitives;
    private final transient Mission mission;
    private final transient CountDownLatch ready;
    private transient volatile Thread thread;
    private transient volatile FIPAException registrationFailure;

    MaslJadeAgent(int proxyId, AgentImplementation implementation, PrimitiveTable primitives, Mission mission,
            CountDownLatch ready) {
        this.proxyId = proxyId;
        this.implementation = implementation;
        this.primitives = primitives;
        this.mission = mission;
        this.ready = ready;
    }

    @Override
    protected void setup() {
        thread = Thread.currentThread();
        try {
            DFService.register(this, description());
        } catch (FIPAException e) {
            registrationFailure = e;
        }
        addBehaviour(new RequestServer());
        ready.countDown();
    }

    private DFAgentDescription description() {
        DFAgentDescription description = new DFAgentDescription();
        description.setName(getAID());
        ServiceDescription type = new ServiceDescription();
        type.setType(TYPE_SERVICE);
        type.setName(primitives.type().shortName());
        type.addProperties(new Property("class", primitives.type().fullClassName()));
        description.addServices(type);
        for (Primitive primitive : primitives.primitives()) {
            ServiceDescription service = new ServiceDescription();
            service.setType(PRIMITIVE_SERVICE);
            service.setName(primitive.name());
            service.addLanguages(AclInvocations.LANGUAGE);
            service.addOntologies(AclInvocations.ONTOLOGY);
            service.addProperties(new Property("signature", primitive.signature()));
            description.addServices(service);
        }
        return description;
    }

    @Override
    protected void takeDown() {
        if (registrationFailure == null) {
            try {
                DFService.deregister(this);
            } catch (FIPAException e) {
                // The platform is going away with its DF: nothing is left to deregister from.
            }
        }
    }

    /** Why the DF refused the registration, or null if it accepted it. */
    FIPAException registrationFailure() {
        return registrationFailure;
    }

    /** The agent's own JADE thread (set once it has started). */
    Thread thread() {
        return thread;
    }

    /** Adds a behaviour from another thread: JADE's scheduler is thread-safe for this. */
    void host(Behaviour behaviour) {
        addBehaviour(behaviour);
    }

    private void answer(ACLMessage message) {
        if (message.getPerformative() == ACLMessage.NOT_UNDERSTOOD) {
            return; // never answer a NOT_UNDERSTOOD with another: two agents would echo forever
        }
        PrimitiveTable.Call call;
        try {
            call = primitives.bind(AclInvocations.readRequest(message));
        } catch (ContentException problem) {
            send(AclInvocations.notUnderstood(message, problem));
            return;
        }
        String primitive = call.primitive().name();
        // A FIPA agent is an "other" (MASL §11): the runtime filters the request by the agent's state
        // when the agent serves it, and runs either the primitive or the refusal.
        mission.submitInvocation(proxyId, primitive, () -> serve(message, call),
                () -> send(AclInvocations.reply(message, Reply.Kind.REFUSED, JsonContent.refusal(
                        "the permeability of " + getLocalName() + " denies others invoking " + primitive))));
    }

    /** Runs on the MASL agent's thread, when it serves its invocations and its state allows this one. */
    private void serve(ACLMessage request, PrimitiveTable.Call call) {
        Object result;
        try {
            result = call.invoke(implementation);
        } catch (InvocationTargetException thrown) {
            send(AclInvocations.reply(request, Reply.Kind.FAILED, JsonContent.failure(thrown.getCause())));
            return;
        }
        String content;
        try {
            content = JsonContent.result(result);
        } catch (RuntimeException | StackOverflowError unwritable) {
            // A result whose toString throws, or a collection holding itself: the requester's
            // failure, not the mission's.
            send(AclInvocations.reply(request, Reply.Kind.FAILED, JsonContent.failure(unwritable)));
            return;
        }
        send(AclInvocations.reply(request, Reply.Kind.RESULT, content));
    }

    /** Takes every message addressed to this agent. */
    private final class RequestServer extends CyclicBehaviour {
        private static final long serialVersionUID = 1L;

        @Override
        public void action() {
            ACLMessage message = receive();
            if (message == null) {
                block();
            } else {
                answer(message);
            }
        }
    }
}
