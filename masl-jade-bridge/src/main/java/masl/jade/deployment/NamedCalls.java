package masl.jade.deployment;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import masl.runtime.AgentImplementation;
import masl.runtime.descriptor.AgentType;

/**
 * The mission's side of invocations and attribute accesses that name their member rather than hand
 * over Java code: a deployed agent's of an agent that runs elsewhere than its container. Each runs on
 * the callee's real object, where it is: here for an agent whose program runs here (through its
 * placed body's or external agent's stub, if it has one), in its container for a deployed one. Here,
 * a deployed agent's object is a stub whose primitives are such requests to its container, so that the
 * programs that run here (in-process, placed) invoke it there too.
 */
final class NamedCalls {

    private final Coordination coordination;
    private final Map<Integer, Members> members = new ConcurrentHashMap<>();
    private final Set<Integer> deployed = ConcurrentHashMap.newKeySet();

    NamedCalls(Coordination coordination) {
        this.coordination = coordination;
    }

    /** See {@link Coordination#implementationOf}. */
    AgentImplementation implementationOf(int proxyId, AgentType type, AgentImplementation made, boolean isDeployed) {
        if (type == null) {
            return made;
        }
        Members bound = new Members(type, made.getClass());
        members.put(proxyId, bound);
        if (!isDeployed) {
            return made;
        }
        deployed.add(proxyId);
        DeployedBody body = new DeployedBody(proxyId, bound, this);
        AgentImplementation stub = Members.STUBS.instantiate(made.getClass(), bound.methods(), body);
        body.of(stub);
        return stub;
    }

    /** Runs {@code primitive} of agent {@code proxyId} with {@code args} (tagged values) on its real object; its result. */
    Object invoke(int proxyId, String primitive, JsonNode args) {
        List<Object> values = new ArrayList<>();
        args.forEach(arg -> values.add(Values.fromJson(arg, coordination.agents())));
        return of(proxyId).invoke(coordination.agents().get(proxyId), primitive, values);
    }

    /** The value of attribute {@code attribute} of agent {@code proxyId}, read where the agent runs. */
    Object read(int proxyId, String attribute) {
        Members owner = of(proxyId);
        if (deployed.contains(proxyId)) {
            JsonNode value = coordination.ask(proxyId, request("read").put("attribute", attribute)).get("value");
            return Values.fromJson(value, coordination.agents());
        }
        return owner.read(coordination.agents().get(proxyId), attribute);
    }

    /** Sets attribute {@code attribute} of agent {@code proxyId} to {@code value} (tagged), where the agent runs. */
    void write(int proxyId, String attribute, JsonNode value) {
        Members owner = of(proxyId);
        if (deployed.contains(proxyId)) {
            ObjectNode write = request("write").put("attribute", attribute);
            write.set("value", value);
            coordination.ask(proxyId, write);
            return;
        }
        owner.write(coordination.agents().get(proxyId), attribute, Values.fromJson(value, coordination.agents()));
    }

    /** A deployed agent's primitive, called on its object here: run in its container, on its real object. */
    Object inContainer(int proxyId, String primitive, Object[] args) {
        ObjectNode request = request("primitive").put("primitive", primitive);
        ArrayNode values = request.putArray("args");
        for (Object arg : args) {
            values.add(Values.toJson(arg));
        }
        JsonNode result = coordination.ask(proxyId, request).get("value");
        return Values.fromJson(result, coordination.agents());
    }

    private Members of(int proxyId) {
        Members of = members.get(proxyId);
        if (of == null) {
            throw new IllegalArgumentException("agent " + proxyId + " has no type whose members a call may name");
        }
        return of;
    }

    private static ObjectNode request(String kind) {
        return JsonNodeFactory.instance.objectNode().put("kind", kind);
    }
}
