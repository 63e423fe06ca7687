package masl.jade.deployment;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
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

    @Test
    void whatIsHeldWhileAnAgentStaysBusyGoesOnceNothingMoreIsAddedInOneBatch() throws InterruptedException {
        BlockingQueue<ObjectNode> sent = new LinkedBlockingQueue<>();
        // Two agents busy; one answers, the other stays busy (a long primitive): its answer must not hold the first's.
        Outbox outbox = new Outbox(sent::add, 2);
        outbox.add(message("answer"), -1);
        outbox.add(message("yield"), 0);
        ObjectNode batch = sent.poll(10, TimeUnit.SECONDS);
        assertNotNull(batch, "what was held never went");
        assertEquals(List.of("answer", "yield"), kinds(batch));
        outbox.add(message("answer"), 0);
        ObjectNode next = sent.poll(10, TimeUnit.SECONDS);
        assertNotNull(next, "what was held after the first batch never went");
        assertEquals(List.of("answer"), kinds(next));
        assertNull(sent.poll(100, TimeUnit.MILLISECONDS), "nothing more was added");
    }

    private static ObjectNode message(String kind) {
        return JsonNodeFactory.instance.objectNode().put("kind", kind).put("agent", 0);
    }

    private static List<String> kinds(ObjectNode batch) {
        return Batch.each(batch).stream().map(message -> message.path("kind").asText()).toList();
    }
}
