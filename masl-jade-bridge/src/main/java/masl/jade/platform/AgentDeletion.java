package masl.jade.platform;

import jade.wrapper.AgentController;
import jade.wrapper.StaleProxyException;
import java.time.Duration;
import java.util.List;

/**
 * Deletes agents of one container one after another, each gone from the container before the next
 * is asked to end. JADE 4.3 takes an ending agent out of its container's agent table outside the
 * table's lock: agents ending together can corrupt it for good, and the AMS, which reads it to shut
 * the platform down, then never ends the container ("Cannot kill container Main-Container").
 * Public for code that starts agents of its own in a platform (the bench's pingers).
 */
public final class AgentDeletion {

    private AgentDeletion() {
    }

    /**
     * Kills each agent and waits until its container no longer knows it, all within {@code timeout};
     * past it, the rest are killed without waiting.
     */
    public static void oneByOne(List<AgentController> controllers, Duration timeout) throws InterruptedException {
        long deadline = System.nanoTime() + timeout.toNanos();
        for (AgentController controller : controllers) {
            try {
                controller.kill();
            } catch (StaleProxyException alreadyGone) {
                continue;
            }
            // JADE tells no one when an agent has left its table: asked again every millisecond.
            while (isKnown(controller) && System.nanoTime() - deadline < 0) {
                Thread.sleep(1);
            }
        }
    }

    private static boolean isKnown(AgentController controller) {
        try {
            controller.getState();
            return true;
        } catch (StaleProxyException gone) {
            return false;
        }
    }
}
