package masl.jade.placement;

import jade.core.AID;
import jade.lang.acl.ACLMessage;
import java.util.Collection;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;
import masl.jade.acl.Conversations;

/**
 * While the mission runs, asks each container hosting its bodies or deployed agents every
 * {@value #PERIOD_MILLIS} ms whether it is still there ({@value Conversations#ALIVE}, signed): a deployed
 * agent in the middle of a step, or a body in the middle of a call, sends nothing, and the AMS's removal
 * event does not reach every coordinator, so the AMS's {@code FAILURE} for an undeliverable check is what
 * tells the coordinator, within a period or two, that the container left, closed or killed
 * ({@link CoordinatorAgent} reports it unreachable).
 */
final class ContainerWatch implements AutoCloseable {

    private static final long PERIOD_MILLIS = 500;

    private final ScheduledExecutorService timer = Executors.newSingleThreadScheduledExecutor(work -> {
        Thread thread = new Thread(work, "masl-container-watch");
        thread.setDaemon(true);
        return thread;
    });
    /** The check last sent to each container, forgotten when the next is sent: only an undeliverable one matters. */
    private final Map<AID, ACLMessage> asked = new ConcurrentHashMap<>();

    ContainerWatch(CoordinatorAgent coordinator, Supplier<Collection<AID>> containers) {
        timer.scheduleWithFixedDelay(() -> {
            for (AID container : containers.get()) {
                ACLMessage previous = asked.remove(container);
                if (previous != null) {
                    coordinator.forget(previous);
                }
                ACLMessage check = Conversations.request(container, Conversations.ALIVE, "{}");
                coordinator.ask(check);
                asked.put(container, check);
            }
        }, PERIOD_MILLIS, PERIOD_MILLIS, TimeUnit.MILLISECONDS);
    }

    @Override
    public void close() {
        timer.shutdownNow();
    }
}
