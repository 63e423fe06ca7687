package masl.jade.platform;

import jade.content.ContentElement;
import jade.content.onto.basic.Result;
import jade.core.Agent;
import jade.core.ContainerID;
import jade.core.behaviours.OneShotBehaviour;
import jade.domain.FIPAService;
import jade.domain.JADEAgentManagement.QueryPlatformLocationsAction;
import jade.lang.acl.ACLMessage;
import jade.wrapper.AgentController;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The names of the containers a platform's AMS counts at this moment, asked the way JADE's tools
 * ask ({@code QueryPlatformLocationsAction}) by a short-lived agent of the platform.
 */
public final class PlatformContainers extends Agent {
    private static final long serialVersionUID = 1L;
    private static final AtomicInteger ASKERS = new AtomicInteger();

    private final transient CompletableFuture<List<String>> names = new CompletableFuture<>();

    private PlatformContainers() {
    }

    public static List<String> of(JadePlatform platform) throws Exception {
        PlatformContainers asker = new PlatformContainers();
        AgentController controller = platform.container().acceptNewAgent("container-lister-"
                + ASKERS.incrementAndGet(), asker);
        controller.start();
        try {
            return asker.names.get(30, TimeUnit.SECONDS);
        } finally {
            AgentDeletion.oneByOne(List.of(controller), Duration.ofSeconds(10));
        }
    }

    @Override
    protected void setup() {
        addBehaviour(new OneShotBehaviour(this) {
            private static final long serialVersionUID = 1L;

            @Override
            public void action() {
                try {
                    ACLMessage request = AmsRequests.request(myAgent, new QueryPlatformLocationsAction());
                    ContentElement answer = getContentManager().extractContent(
                            FIPAService.doFipaRequestClient(myAgent, request, 20_000));
                    List<String> found = new ArrayList<>();
                    for (Object location : ((Result) answer).getItems().toArray()) {
                        found.add(((ContainerID) location).getName());
                    }
                    names.complete(found);
                } catch (Exception e) {
                    names.completeExceptionally(e);
                }
            }
        });
    }
}
