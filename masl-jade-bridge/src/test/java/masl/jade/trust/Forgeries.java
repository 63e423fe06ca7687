package masl.jade.trust;

import jade.core.AID;
import jade.lang.acl.ACLMessage;

/** Messages a member of a mission could make: signed with its secret under the member's own name. */
public final class Forgeries {

    private Forgeries() {
    }

    /** {@code message} signed by {@code sender} with {@code secret}, as its first message to its receiver. */
    public static ACLMessage signedBy(MissionSecret secret, AID sender, ACLMessage message) {
        return MissionChannel.of(sender.getLocalName(), secret).sign(message, sender);
    }
}
