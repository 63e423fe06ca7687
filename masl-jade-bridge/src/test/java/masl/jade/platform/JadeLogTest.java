package masl.jade.platform;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** What JADE logs that its sender is told otherwise is not printed. */
class JadeLogTest {

    @Test
    void aMessageWhoseAddresseeLeftIsTheSendersToReport() {
        assertTrue(JadeLog.toldToTheSender("Error serving H-Command jade.core.messaging.Messaging/1:"
                + " jade.core.NotFoundException: Messaging service slice failed to find ( agent-identifier :name"
                + " masl-container-c2@127.0.0.1:47312/JADE )"));
    }

    @Test
    void otherFailuresToServeACommandAreLogged() {
        assertFalse(JadeLog.toldToTheSender("Error serving H-Command jade.core.messaging.Messaging/1:"
                + " jade.core.IMTPException: Error dispatching command"));
        assertFalse(JadeLog.toldToTheSender("Error serving H-Command jade.core.management.AgentManagement/3:"
                + " jade.core.NotFoundException: Messaging service slice failed to find x"));
    }
}
