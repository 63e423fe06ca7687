package masl.jade;

import jade.core.AID;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.domain.FIPAAgentManagement.Property;
import jade.domain.FIPAAgentManagement.ServiceDescription;
import jade.domain.FIPANames;
import masl.jade.acl.AclInvocations;
import masl.jade.placement.MaslContainer;
import masl.runtime.descriptor.Primitive;

/**
 * What the bridge's agents register with the DF.
 *
 * <p>Public for the coordinator and the containers ({@code placement}), which register these entries
 * too, and for the search for a container's claimants ({@code trust}).
 */
public final class DfEntries {

    /** DF service type of a MASL agent's type; the service's name is the type's short name. */
    static final String TYPE_SERVICE = "masl-agent";
    /** DF service type of each primitive; the service's name is the primitive's name. */
    public static final String PRIMITIVE_SERVICE = "masl-primitive";
    /** DF service type of a container hosting bodies ({@link MaslContainer}); named after the container. */
    public static final String CONTAINER_SERVICE = "masl-container";
    /** DF service type of the coordinator of a mission spanning containers. */
    public static final String COORDINATOR_SERVICE = "masl-coordinator";

    private DfEntries() {
    }

    /**
     * A MASL agent: its type and one service per primitive, each answering fipa-request in language
     * json, ontology masl (the type's service also QUERY_REF of attributes and SUBSCRIBE to events).
     */
    static DFAgentDescription maslAgent(AID agent, PrimitiveTable primitives) {
        DFAgentDescription description = new DFAgentDescription();
        description.setName(agent);
        ServiceDescription type = new ServiceDescription();
        type.setType(TYPE_SERVICE);
        type.setName(primitives.type().shortName());
        type.addProperties(new Property("class", primitives.type().fullClassName()));
        speaksMasl(type);
        description.addServices(type);
        for (Primitive primitive : primitives.primitives()) {
            ServiceDescription service = new ServiceDescription();
            service.setType(PRIMITIVE_SERVICE);
            service.setName(primitive.name());
            speaksMasl(service);
            service.addProperties(new Property("signature", primitive.signature()));
            description.addServices(service);
        }
        return description;
    }

    /** What a FIPA agent needs to talk to the service: protocol fipa-request, language json, ontology masl. */
    private static void speaksMasl(ServiceDescription service) {
        service.addProtocols(FIPANames.InteractionProtocol.FIPA_REQUEST);
        service.addLanguages(AclInvocations.LANGUAGE);
        service.addOntologies(AclInvocations.ONTOLOGY);
    }

    /** One service of {@code serviceType} named {@code name}: a search template too. */
    public static DFAgentDescription service(AID agent, String serviceType, String name) {
        DFAgentDescription description = new DFAgentDescription();
        if (agent != null) {
            description.setName(agent);
        }
        ServiceDescription service = new ServiceDescription();
        service.setType(serviceType);
        service.setName(name);
        description.addServices(service);
        return description;
    }
}
