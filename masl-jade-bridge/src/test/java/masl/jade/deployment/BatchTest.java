package masl.jade.deployment;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.IntNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.LongNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;
import masl.runtime.DeployedPrograms;
import org.junit.jupiter.api.Test;

/** What a batch carries over the wire: every message, in order, alike ones as one run. */
class BatchTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    @Test
    void everyMessageComesBackInItsOrderAfterTheWire() throws Exception {
        List<ObjectNode> messages = new ArrayList<>();
        messages.add(wakeUp(4, 10));
        messages.add(wakeUp(6, 11));
        messages.add(JsonNodeFactory.instance.objectNode().put("kind", "attend").put("seq", 12));
        messages.add(wakeUp(8, 13).put("pc", 9));
        messages.add(wakeUp(10, 14));
        messages.add(JsonNodeFactory.instance.objectNode().put("kind", "yield").put("agent", 3).put("journal", "x\n"));
        messages.add(JsonNodeFactory.instance.objectNode().put("kind", "yield").put("agent", 5));
        assertEquals(messages, overTheWire(batchOf(messages)));
    }

    @Test
    void aLockStepWaveIsOneRunOfItsAgentsAndNumbers() {
        List<ObjectNode> wave = new ArrayList<>();
        for (int agent = 0; agent < 500; agent++) {
            wave.add(wakeUp(agent, 1_000 + agent));
        }
        ObjectNode batch = batchOf(wave);
        assertEquals(1, batch.get("runs").size(), batch.toString());
        ObjectNode run = (ObjectNode) batch.get("runs").get(0);
        assertEquals(500, run.get("agent").size());
        assertEquals(1_499, run.get("seq").get(499).intValue());
        assertEquals(List.of("kind", "value", "resumed", "pc", "atRest", "done"), fieldNames((ObjectNode) run.get("like")));
    }

    @Test
    void messagesThatNameNoAgentAndNoNumberAreEachTheirOwnRun() {
        ObjectNode end = JsonNodeFactory.instance.objectNode().put("kind", "end");
        ObjectNode batch = batchOf(List.of(end, end.deepCopy()));
        assertEquals(2, batch.get("runs").size(), batch.toString());
        assertEquals(List.of(end, end), Batch.each(batch));
    }

    @Test
    void aRunNotWellMadeIsOneMessageNamingNoAgent() throws Exception {
        ObjectNode batch = (ObjectNode) JSON.readTree("""
                {"kind":"batch","runs":[{"like":{"kind":"yield"},"agent":[1,2]},{"like":3},{"like":{"kind":"yield"},"agent":7},5,{"like":{"kind":"yield","agent":4},"seq":[1]}]}""");
        List<ObjectNode> each = Batch.each(batch);
        assertEquals(List.of(1, 2, -1, -1, -1, -1), each.stream().map(message -> message.path("agent").asInt(-1)).toList());
    }

    @Test
    void aMessageOfARunChangedByItsTakerLeavesTheOthersAsTheyCame() throws Exception {
        List<ObjectNode> each = overTheWire(batchOf(List.of(wakeUp(1, 10), wakeUp(2, 11), wakeUp(3, 12))));
        each.get(0).put("pc", 9).remove("seq");
        assertEquals(wakeUp(1, 10).put("pc", 9).without("seq"), each.get(0));
        assertEquals(List.of(wakeUp(2, 11), wakeUp(3, 12)), each.subList(1, 3));
        assertEquals(wakeUp(3, 12), JSON.readTree(each.get(2).toString()));
    }

    @Test
    void alikeMessagesWhoseFieldsCameInAnotherOrderAreRunsOfTheirOwnAndComeBackAsTheyWent() throws Exception {
        ObjectNode first = JsonNodeFactory.instance.objectNode().put("kind", "yield").put("pc", 3).put("agent", 1);
        ObjectNode second = JsonNodeFactory.instance.objectNode().put("pc", 3).put("kind", "yield").put("agent", 2);
        ObjectNode batch = batchOf(List.of(first, second));
        assertEquals(2, batch.get("runs").size(), batch.toString());
        assertEquals(List.of(first, second), overTheWire(batch));
    }

    @Test
    void wakeUpsSharingTheirFieldsAreOneRunAndEachComesBackWithItsAgentAndNumber() throws Exception {
        ObjectNode fields = new WakeUps().of(true, 7, new DeployedPrograms.AtRest(41, true));
        List<Batch.Held> wave = new ArrayList<>();
        for (int agent = 0; agent < 3; agent++) {
            wave.add(new Batch.Held(fields, IntNode.valueOf(agent), LongNode.valueOf(10 + agent)));
        }
        ObjectNode batch = Batch.of(wave);
        assertEquals(1, batch.get("runs").size(), batch.toString());
        assertEquals(List.of(wakeUp(0, 10).without("done"), wakeUp(1, 11).without("done"), wakeUp(2, 12).without("done")),
                overTheWire(batch));
    }

    @Test
    void aMessageThatIsNoBatchIsItself() {
        ObjectNode one = wakeUp(1, 2);
        assertEquals(List.of(one), Batch.each(one));
    }

    /** A stand-in's answer that resumes its agent's step at a barrier's trip, as the mission sends it. */
    private static ObjectNode wakeUp(int agent, int seq) {
        ObjectNode answer = JsonNodeFactory.instance.objectNode().put("kind", "answer").put("value", false)
                .put("resumed", true).put("pc", 7).put("seq", seq);
        answer.putObject("atRest").put("latest", 41).put("barrier", true);
        answer.putArray("done");
        return answer.put("agent", agent);
    }

    /** The batch of {@code messages}, as an outbox makes it of copies of them. */
    private static ObjectNode batchOf(List<ObjectNode> messages) {
        return Batch.of(messages.stream().map(message -> Batch.Held.of(message.deepCopy())).toList());
    }

    private static List<ObjectNode> overTheWire(ObjectNode batch) throws Exception {
        return Batch.each((ObjectNode) JSON.readTree(batch.toString()));
    }

    private static List<String> fieldNames(ObjectNode object) {
        List<String> names = new ArrayList<>();
        object.fieldNames().forEachRemaining(names::add);
        return names;
    }
}
