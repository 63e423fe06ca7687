package masl.jade.deployment;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;

/** What an outbox puts on its wire: batches of the messages added, never an empty one. */
class OutboxTest {

    @Test
    void aMessageTheOtherSideWaitsForGoesAloneAndAtOnceWhenNothingIsHeld() {
        List<ObjectNode> sent = new CopyOnWriteArrayList<>();
        Outbox outbox = new Outbox(sent::add, 0);
        outbox.now(message("ran"));
        assertEquals(1, sent.size(), sent.toString());
        assertEquals("batch", sent.get(0).path("kind").asText());
        assertEquals(List.of("ran"), kinds(sent.get(0)));
    }

    @Test
    void aMessageThatLetsTheLastBusyAgentGoOnSendsWhatIsHeldWithIt() {
        List<ObjectNode> sent = new CopyOnWriteArrayList<>();
        Outbox outbox = new Outbox(sent::add, 1);
        outbox.add(message("answer"), -1);
        assertEquals(1, sent.size(), sent.toString());
        assertEquals(List.of("answer"), kinds(sent.get(0)));
    }

    private static ObjectNode message(String kind) {
        return JsonNodeFactory.instance.objectNode().put("kind", kind).put("agent", 0);
    }

    private static List<String> kinds(ObjectNode batch) {
        return Batch.each(batch).stream().map(message -> message.path("kind").asText()).toList();
    }
}
