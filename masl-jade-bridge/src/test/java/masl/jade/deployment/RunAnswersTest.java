package masl.jade.deployment;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import masl.runtime.EntryDefinition;
import masl.runtime.Mode;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * What the mission asks of a container (a call to run, a primitive or attribute by name) is answered
 * only by a {@code ran} for the agent it was asked for: another container of the mission, which may
 * speak for its own agents only, cannot answer for the agent asked.
 */
@Timeout(30)
class RunAnswersTest {

    private static final JsonNodeFactory JSON = JsonNodeFactory.instance;

    @Test
    void aRunIsAnsweredOnlyForTheAgentItWasAskedFor() throws Exception {
        BlockingQueue<ObjectNode> sent = new LinkedBlockingQueue<>();
        Coordination coordination = new Coordination(EntryDefinition.main("main", Mode.SYNCHRONOUS),
                proxyId -> sent::add, text -> { });
        CompletableFuture<ObjectNode> asked = CompletableFuture.supplyAsync(
                () -> coordination.ask(1, JSON.objectNode().put("kind", "read").put("attribute", "total")));
        ObjectNode request = Batch.each(sent.poll(10, TimeUnit.SECONDS)).get(0);
        long run = request.get("run").longValue();

        // Agent 0's container answers first: were it taken, the run would end with its 666.
        coordination.receive(ran(0, run, 666));
        coordination.receive(ran(1, run, 3));
        assertEquals(3, asked.get(10, TimeUnit.SECONDS).get("value").get("int").intValue());
    }

    private static ObjectNode ran(int agent, long run, int value) {
        ObjectNode ran = JSON.objectNode().put("kind", "ran").put("agent", agent).put("run", run).put("outcome", "ran");
        ran.putObject("value").put("int", value);
        return ran;
    }
}
