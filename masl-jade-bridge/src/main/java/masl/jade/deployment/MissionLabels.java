package masl.jade.deployment;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.BooleanNode;
import com.fasterxml.jackson.databind.node.IntNode;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import masl.runtime.AgentContext;
import masl.runtime.Label;

/**
 * The labels (§10) of a mission's deployed agents, held by the mission, the one authority: a
 * container holds views ({@link RemoteLabel}) whose requests this performs on the mission's label.
 * A label a container made is made here when a request first names it, by the agent that made it
 * (its key is {@code proxyId.n}); one made in the mission gets a key when it first travels (an
 * {@code SLabel} an agent of the mission's JVM made, read by a deployed one).
 */
final class MissionLabels {

    private final Coordination coordination;
    private final Map<String, Label> byKey = new HashMap<>();
    private final Map<Label, String> keys = new IdentityHashMap<>();
    private long made;

    MissionLabels(Coordination coordination) {
        this.coordination = coordination;
    }

    /** The labels as agent {@code agent}'s request names them, made with its context {@code ctx}. */
    Values.Labels of(StandIn agent, AgentContext ctx) {
        return new Values.Labels() {
            @Override
            public Label label(String key) {
                return MissionLabels.this.label(key, agent, ctx);
            }

            @Override
            public String key(Label label) {
                return MissionLabels.this.key(label);
            }
        };
    }

    private synchronized Label label(String key, StandIn agent, AgentContext ctx) {
        Label label = byKey.get(key);
        if (label == null) {
            if (!key.startsWith(agent.id() + ".")) {
                throw new IllegalArgumentException("agent " + agent.id() + " names label " + key
                        + ", which it did not make and was not given");
            }
            label = ctx.newLabel();
            byKey.put(key, label);
            keys.put(label, key);
        }
        return label;
    }

    private synchronized String key(Label label) {
        return keys.computeIfAbsent(label, travelling -> {
            String key = "mission." + ++made;
            byKey.put(key, travelling);
            return key;
        });
    }

    /** Performs label request {@code op} ({@code label-op} of {@link RemoteLabel}) of {@code agent}. */
    JsonNode perform(StandIn agent, AgentContext ctx, String op, JsonNode request) {
        Label label = label(request.get("label").textValue(), agent, ctx);
        return switch (op) {
            case "isFinished" -> BooleanNode.valueOf(label.isFinished());
            case "remaining" -> IntNode.valueOf(label.getRemainingInvocations());
            case "free" -> {
                label.free();
                yield null;
            }
            case "register" -> {
                register(agent, ctx, label, request);
                yield null;
            }
            case "store" -> {
                coordination.named().write(request.get("owner").intValue(), request.get("attribute").textValue(),
                        request.get("value"));
                yield null;
            }
            default -> throw new IllegalArgumentException("no label request " + op);
        };
    }

    /**
     * Registers the call the agent's program made with {@code label}; the program is told the call is
     * over once the label has counted it and its store (if any) has run in the container.
     */
    private void register(StandIn agent, AgentContext ctx, Label label, JsonNode request) {
        long call = request.get("call").longValue();
        CompletableFuture<Object> invocation = agent.call(call);
        if (invocation == null) {
            throw new IllegalArgumentException("agent " + agent.id() + " has no call " + call + " under way");
        }
        JsonNode store = request.get("store");
        if (store == null) {
            agent.track(call, label.register(invocation));
        } else if (request.has("attribute")) {
            int owner = request.get("owner").intValue();
            String attribute = request.get("attribute").textValue();
            agent.track(call, label.register(invocation, value -> storedElsewhere(agent, ctx, store.longValue(),
                    owner, attribute, value)));
        } else {
            agent.track(call, label.register(invocation,
                    value -> coordination.run(agent.id(), store.longValue(), StandIn.ended(value))));
        }
    }

    /**
     * A store into attribute {@code attribute} of agent {@code owner}, which runs elsewhere than the
     * caller: the caller's container makes the value (the call's result is there), written where the
     * owner runs. As in-process, a label's store checks no permeability. A value that does not travel,
     * or a container gone, makes the caller perceive {@code uncaught_exception}, as a write by name
     * does; the label still counts the call.
     */
    private void storedElsewhere(StandIn agent, AgentContext ctx, long store, int owner, String attribute,
            Object value) {
        try {
            JsonNode written = coordination.apply(agent.id(), store, StandIn.ended(value));
            coordination.named().write(owner, attribute, written);
        } catch (RuntimeException failed) {
            ctx.uncaughtException(failed);
        }
    }
}
