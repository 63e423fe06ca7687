package masl.jade.platform;

import jade.core.AID;
import jade.core.Agent;
import jade.domain.FIPAException;
import jade.domain.FIPAService;
import jade.domain.JADEAgentManagement.KillAgent;

/** What any member of a platform may ask its AMS, as JADE's tools do: the tests of impostors do it. */
public final class AmsActions {

    private AmsActions() {
    }

    /** Has the AMS kill {@code victim}, asked by {@code asker}; returns once the AMS has done it. */
    public static void kill(Agent asker, AID victim) throws FIPAException {
        KillAgent kill = new KillAgent();
        kill.setAgent(victim);
        FIPAService.doFipaRequestClient(asker, AmsRequests.request(asker, kill), 20_000);
    }
}
