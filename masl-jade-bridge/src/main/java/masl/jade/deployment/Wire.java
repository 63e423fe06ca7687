package masl.jade.deployment;

import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * One direction of the coordination between a mission and a container that runs deployed agents'
 * programs: JSON messages, delivered in the order sent. Over JADE, each is a signed ACL message of
 * the mission's channel; in a test, a queue.
 */
@FunctionalInterface
public interface Wire {

    /** Sends {@code message}; never blocks for its answer. */
    void send(ObjectNode message);
}
