package masl.jade.trust;

import jade.core.AID;
import jade.core.Agent;
import jade.domain.DFService;
import jade.domain.FIPAAgentManagement.DFAgentDescription;
import jade.domain.FIPAException;
import jade.lang.acl.ACLMessage;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.function.Consumer;
import java.util.function.Function;
import masl.jade.DfEntries;
import masl.jade.acl.Conversations;
import masl.jade.platform.JadeException;

/**
 * Who is container {@code NAME}: the DF lists any agent that registers the service, so a DF entry
 * proves nothing. The coordinator asks every agent the DF lists as the container to host its bodies
 * ({@value Conversations#PLACE}), as each appears, and binds the placement to the first that answers
 * with the mission's signature ({@link MissionChannel}): the answer of an agent without the secret
 * is refused as it comes (the coordinator's {@code ask} completes only with a signed answer), so the
 * real container wins whatever the order in which it and others registered. Each other claimant is
 * said in one line and ignored from then on.
 *
 * <p>Public for the coordinator's placement ({@code placement}): the trust checks live in this package
 * alone.
 */
public final class ContainerClaims {

    private static final long SEARCH_PERIOD_MILLIS = 50;

    private final Agent coordinator;
    private final Function<ACLMessage, CompletableFuture<ACLMessage>> ask;
    private final Consumer<ACLMessage> forget;
    private final String container;
    private final Duration within;
    private final Consumer<String> problems;
    private final Map<AID, Claim> claims = new LinkedHashMap<>();

    /** The container that proved itself, and its signed answer to the placement. */
    public record Proven(AID container, ACLMessage answer) {
    }

    private record Claim(ACLMessage request, CompletableFuture<ACLMessage> answer) {
    }

    /**
     * @param coordinator the agent that searches the DF for claimants, and whose AMS reports a claimant gone
     * @param ask         sends a request signed and completes its future with the claimant's signed
     *                    answer only, or with the AMS's {@code FAILURE} when the claimant is gone
     * @param forget      stops waiting for the answer to a request
     */
    public ContainerClaims(Agent coordinator, Function<ACLMessage, CompletableFuture<ACLMessage>> ask,
            Consumer<ACLMessage> forget, String container, Duration within, Consumer<String> problems) {
        this.coordinator = coordinator;
        this.ask = ask;
        this.forget = forget;
        this.container = container;
        this.within = within;
        this.problems = problems;
    }

    /**
     * Asks the claimants of the container to create the bodies {@code placement} names until one
     * proves it is the container, waiting up to the time limit for it to join.
     *
     * @throws JadeException if none proved it within the limit, or the DF cannot be searched
     */
    public Proven place(String placement) throws InterruptedException {
        long deadline = System.nanoTime() + within.toNanos();
        try {
            while (true) {
                for (AID claimant : claimants()) {
                    claims.computeIfAbsent(claimant, asked -> {
                        ACLMessage request = Conversations.request(asked, Conversations.PLACE, placement);
                        return new Claim(request, ask.apply(request));
                    });
                }
                for (Map.Entry<AID, Claim> claim : claims.entrySet()) {
                    ACLMessage answer = provenAnswer(claim.getValue().answer());
                    if (answer != null) {
                        claims.remove(claim.getKey());
                        return new Proven(claim.getKey(), answer);
                    }
                }
                if (System.nanoTime() - deadline > 0) {
                    throw new JadeException(unproven());
                }
                Thread.sleep(SEARCH_PERIOD_MILLIS);
            }
        } finally {
            for (Map.Entry<AID, Claim> other : claims.entrySet()) {
                forget.accept(other.getValue().request());
                problems.accept("container " + container + " is claimed by " + other.getKey().getName()
                        + ", which did not prove it holds the mission's secret: ignored");
            }
        }
    }

    /**
     * The answer of a claimant that holds the secret (the coordinator completes a claim's future only
     * with a signed answer, or with the AMS's {@code FAILURE} when the claimant is gone); null if none yet.
     */
    private ACLMessage provenAnswer(CompletableFuture<ACLMessage> answer) throws InterruptedException {
        if (!answer.isDone() || answer.isCompletedExceptionally()) {
            return null;
        }
        try {
            ACLMessage message = answer.get();
            return message.getSender().equals(coordinator.getAMS()) ? null : message;
        } catch (ExecutionException impossible) {
            return null;
        }
    }

    private List<AID> claimants() {
        try {
            List<AID> found = new ArrayList<>();
            for (DFAgentDescription entry : DFService.search(coordinator,
                    DfEntries.service(null, DfEntries.CONTAINER_SERVICE, container))) {
                found.add(entry.getName());
            }
            return found;
        } catch (FIPAException e) {
            throw new JadeException("the DF did not answer a search for container " + container, e);
        }
    }

    private String unproven() {
        if (claims.isEmpty()) {
            return "container " + container + " did not join the platform within " + within
                    + " (start it with: masl container --main-host HOST --main-port PORT --name " + container + ")";
        }
        return "no agent claiming to be container " + container + " proved it holds the mission's secret within "
                + within + " (its answers were refused: is it given this mission's secret file?)";
    }
}
