package masl.missions.fipa;

import jade.core.Agent;
import jade.domain.DFService;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.domain.FIPAAgentManagement.ServiceDescription;
import jade.domain.FIPAException;

/** The DF registration of the example's JADE agents, done the ordinary JADE way. */
final class Directory {

    private Directory() {
    }

    /** Registers {@code agent} as offering {@code service}; false if the DF refused. */
    static boolean register(Agent agent, ServiceDescription service) {
        DFAgentDescription description = new DFAgentDescription();
        description.setName(agent.getAID());
        description.addServices(service);
        try {
            DFService.register(agent, description);
            return true;
        } catch (FIPAException e) {
            return false;
        }
    }

    static void deregister(Agent agent) {
        try {
            DFService.deregister(agent);
        } catch (FIPAException e) {
            // The platform is going away with its DF.
        }
    }
}
