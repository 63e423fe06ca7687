package masl.jade.deployment;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Iterator;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.LinkedBlockingQueue;
import masl.runtime.AgentContext;
import masl.runtime.AgentProgram;
import masl.runtime.DeployedPrograms;
import masl.runtime.Reaction;
import masl.runtime.RemotePrimitiveException;

/**
 * A deployed agent's program as its mission runs it: a step is the container's. {@link #resume}
 * tells the container to run the agent's program from here, then performs each request the program
 * makes on this agent's context, on this thread (the one the mission's scheduler gave the step), and
 * answers it, until the container says the step is over. The program's reactions and MASL source are
 * those of the same generated class, made here too ({@code twin}), whose code never runs here.
 */
final class StandIn extends AgentProgram {

    private final int id;
    private final AgentProgram twin;
    private final Coordination coordination;
    private final BlockingQueue<ObjectNode> requests = new LinkedBlockingQueue<>();
    /** The futures of calls the program made that it has not been told the end of, by call number. */
    private final Map<Long, CompletableFuture<Object>> calls = new ConcurrentHashMap<>();

    StandIn(int id, AgentProgram twin, Coordination coordination) {
        this.id = id;
        this.twin = twin;
        this.coordination = coordination;
    }

    int id() {
        return id;
    }

    void requested(ObjectNode request) {
        requests.add(request);
    }

    void track(long call, CompletableFuture<Object> future) {
        calls.put(call, future);
    }

    CompletableFuture<Object> call(long number) {
        return calls.get(number);
    }

    @Override
    protected void resume(AgentContext ctx) {
        coordination.send(id, withDone(JsonNodeFactory.instance.objectNode().put("kind", "resume").put("pc", pc)));
        while (true) {
            ObjectNode request = coordination.await(id, requests);
            pc = request.get("pc").intValue();
            if ("yield".equals(request.get("kind").textValue())) {
                if (request.has("failed")) {
                    throw new RemotePrimitiveException(request.get("failed").textValue(),
                            request.path("message").textValue());
                }
                return;
            }
            JsonNode value = coordination.calls().perform(this, ctx, request);
            ObjectNode answer = JsonNodeFactory.instance.objectNode().put("kind", "answer").put("pc", pc);
            answer.set("value", value);
            coordination.send(id, withDone(answer));
        }
    }

    /** Adds the calls that are over since the last message, so that the program's futures complete. */
    private ObjectNode withDone(ObjectNode message) {
        ArrayNode done = message.putArray("done");
        for (Iterator<Map.Entry<Long, CompletableFuture<Object>>> it = calls.entrySet().iterator(); it.hasNext(); ) {
            Map.Entry<Long, CompletableFuture<Object>> call = it.next();
            if (call.getValue().isDone()) {
                Object result = call.getValue().join();
                ObjectNode ended = done.addObject().put("call", call.getKey()).put("ran", result != ContextCalls.DENIED);
                if (result instanceof ContextCalls.Result named) {
                    // A call that named its primitive: its result goes to the program that made it.
                    ended.set("value", named.value());
                }
                it.remove();
            }
        }
        return message;
    }

    @Override
    protected int reactionPc(Reaction reaction) {
        return DeployedPrograms.reactionPc(twin, reaction);
    }

    @Override
    protected String sourceAt(int resumptionPoint) {
        return DeployedPrograms.sourceAt(twin, resumptionPoint);
    }

    @Override
    protected String sourceOfCallIn(int resumptionPoint) {
        return DeployedPrograms.sourceOfCallIn(twin, resumptionPoint);
    }
}
