package masl.jade.deployment;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.BooleanNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.NullNode;
import com.fasterxml.jackson.databind.node.TextNode;
import java.lang.reflect.Array;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.CompletableFuture;
import java.util.function.UnaryOperator;
import masl.runtime.AgentContext;
import masl.runtime.AgentImplementation;
import masl.runtime.SharedDeclaration;
import masl.runtime.SharedVariable;
import masl.runtime.entry.Entry;

/**
 * Performs a deployed agent's request on its context in the mission ({@link RemoteContext} makes
 * them): the same {@link AgentContext} call an in-process program makes, with the Java code it hands
 * over standing for the code the container keeps ({@link Callbacks}), run there when the runtime runs it.
 */
final class ContextCalls {

    /** What a call the container ran returns here; the runtime returns its default value, {@link #DENIED}, otherwise. */
    static final Object RAN = new Object();
    static final Object DENIED = new Object();

    /** What a call that named its primitive returns here: its result, which travels to the caller. */
    record Result(JsonNode value) {
    }

    private final Coordination coordination;

    ContextCalls(Coordination coordination) {
        this.coordination = coordination;
    }

    JsonNode perform(StandIn agent, AgentContext ctx, JsonNode request) {
        String op = request.get("op").textValue();
        Blocks blocks = coordination.blocks();
        int id = agent.id();
        switch (op) {
            case "stepBoundary": return bool(ctx.stepBoundary());
            case "loopIteration": return bool(ctx.loopIteration());
            case "busyWaitIteration": return bool(ctx.busyWaitIteration());
            case "enter": return text(ctx.enter(blocks.block(text(request, "block")), request.get("test").booleanValue()).name());
            case "leave": return bool(ctx.leave(blocks.block(text(request, "block"))));
            case "endOfChild": return bool(ctx.endOfChild(blocks.block(text(request, "block"))));
            case "endOfSequence": return bool(ctx.endOfSequence(blocks.sequence(text(request, "sequence"))));
            case "breakOut": ctx.breakOut(blocks.block(text(request, "block"))); return null;
            case "reelect": ctx.reelect(blocks.block(text(request, "block"))); return null;
            case "restart": ctx.restart(blocks.block(text(request, "block"))); return null;
            case "sleep": return bool(ctx.sleep(request.get("ms").longValue()));
            case "await": return bool(ctx.await(agent.call(request.get("call").longValue())));
            case "emit": ctx.emit(blocks.event(text(request, "event")), text(request, "message")); return null;
            case "uncaughtException":
                ctx.uncaughtException(new masl.runtime.RemotePrimitiveException(text(request, "class"),
                        text(request, "message")));
                return null;
            case "messageOf": return text(ctx.messageOf(blocks.event(text(request, "event"))));
            case "endReaction": return bool(ctx.endReaction());
            case "resumeInterrupted": return bool(ctx.resumeInterrupted());
            case "clearEvents": ctx.clearEvents(); return null;
            case "finish": ctx.finish(); return null;
            case "invokeSelf": {
                long call = request.get("call").longValue();
                return bool(ctx.invokeSelf(text(request, "primitive"), DENIED, () -> coordination.run(id, call, null)) == RAN);
            }
            case "invoke":
            case "launch": return queued(agent, ctx, op, request);
            case "readAttribute": {
                if (!request.has("call")) {
                    return readByName(ctx, request);
                }
                long call = request.get("call").longValue();
                return bool(ctx.readAttribute(agent(request, "owner"), text(request, "attribute"), DENIED,
                        new Relayed(() -> coordination.run(id, call, null))) == RAN);
            }
            case "writeAttribute": {
                if (!request.has("call")) {
                    int owner = request.get("owner").intValue();
                    String attribute = text(request, "attribute");
                    return bool(ctx.writeAttribute(agent(request, "owner"), attribute, new Relayed(() -> {
                        try {
                            coordination.named().write(owner, attribute, request.get("value"));
                        } catch (RuntimeException failed) {
                            // Its container gone, say: as a primitive that throws, not the agent's end.
                            ctx.uncaughtException(failed);
                        }
                        return null;
                    })));
                }
                long call = request.get("call").longValue();
                return bool(ctx.writeAttribute(agent(request, "owner"), text(request, "attribute"),
                        new Relayed(() -> coordination.run(id, call, null))));
            }
            case "setAcceptState":
                // The state it is now in: the container's copy of it (OwnPermeability) follows.
                ctx.setAcceptState(text(request, "state"));
                return text(ctx.getAcceptState());
            case "getAcceptState": {
                // "of", not "agent": every call names its caller as "agent".
                int of = request.get("of").intValue();
                return text(of == id ? ctx.getAcceptState() : ctx.getAcceptState(agent(request, "of")));
            }
            case "waitFor": {
                long ms = request.get("ms").longValue();
                return bool(ms < 0 ? ctx.waitFor(text(request, "state")) : ctx.waitFor(text(request, "state"), ms));
            }
            default:
                if (op.startsWith("shared-")) {
                    return shared(agent, ctx, op.substring("shared-".length()), request);
                }
                if (op.startsWith("label-")) {
                    return coordination.labels().perform(agent, ctx, op.substring("label-".length()), request);
                }
                if (op.startsWith("entry-")) {
                    return entry(ctx.entry(blocks.block(text(request, "block"))), op.substring("entry-".length()),
                            request.path("n").intValue());
                }
                throw new IllegalArgumentException("no request " + op + " of a deployed agent");
        }
    }

    private JsonNode queued(StandIn agent, AgentContext ctx, String op, JsonNode request) {
        long call = request.get("call").longValue();
        AgentImplementation callee = agent(request, "callee");
        String primitive = text(request, "primitive");
        Callable<Object> run = callOf(agent, request, call, primitive, "args");
        CompletableFuture<Object> future;
        if ("invoke".equals(op)) {
            future = ctx.invoke(callee, primitive, DENIED, run);
        } else if (request.has("countermeasure")) {
            String countermeasure = text(request, "countermeasure");
            future = ctx.launch(callee, primitive, DENIED, run, countermeasure, callOf(agent, request,
                    request.path("countermeasureCall").longValue(), countermeasure, "countermeasureArgs"));
        } else {
            future = ctx.launch(callee, primitive, DENIED, run);
        }
        agent.track(call, future);
        return null;
    }

    /**
     * The code of a call the request hands over: the primitive named with its arguments {@code args}
     * if the request has them (its result travels back), else the code the container keeps under
     * {@code number}, run there.
     */
    private Callable<Object> callOf(StandIn agent, JsonNode request, long number, String primitive, String args) {
        if (request.has(args)) {
            int callee = request.get("callee").intValue();
            JsonNode values = request.get(args);
            return () -> new Result(Values.toJson(coordination.named().invoke(callee, primitive, values)));
        }
        int id = agent.id();
        return () -> coordination.run(id, number, null);
    }

    /** A read of another agent's attribute by name: its value (tagged), or null if the mission denied it. */
    private JsonNode readByName(AgentContext ctx, JsonNode request) {
        int owner = request.get("owner").intValue();
        String attribute = text(request, "attribute");
        Object read = ctx.readAttribute(agent(request, "owner"), attribute, DENIED, new Relayed(() -> {
            try {
                return new Result(Values.toJson(coordination.named().read(owner, attribute)));
            } catch (RuntimeException failed) {
                // A value that does not travel, its container gone: as a primitive that throws.
                ctx.uncaughtException(failed);
                return DENIED;
            }
        }));
        return read instanceof Result result ? result.value() : NullNode.getInstance();
    }

    @SuppressWarnings("unchecked")
    private JsonNode shared(StandIn agent, AgentContext ctx, String op, JsonNode request) {
        SharedDeclaration<Object> declaration = (SharedDeclaration<Object>) coordination.blocks()
                .shared(text(request, "shared"));
        SharedVariable<Object> variable = ctx.shared(declaration);
        List<AgentImplementation> agents = coordination.agents();
        Values.Labels labels = coordination.labels().of(agent, ctx);
        long call = request.path("call").longValue();
        Class<?> type = declaration.arrayType();
        UnaryOperator<Object> remote = value -> Values.fromJson(
                agent.runInStep(ctx, call, Values.toJson(value, labels)).get("value"), agents, labels, type);
        return switch (op) {
            case "get" -> Values.toJson(variable.get(), labels);
            case "set" -> {
                variable.set(Values.fromJson(request.get("value"), agents, labels, type));
                yield null;
            }
            case "stored" -> {
                JsonNode path = request.get("path");
                Object element = storeElement(variable.get(), path, request.get("value"), type, agents);
                // Stored in the array the variable gave, as the program's own store: busy-wait loops wake.
                variable.stored(element, path.get(0).intValue());
                yield null;
            }
            case "initialise" -> {
                variable.initialise(() -> remote.apply(null));
                yield null;
            }
            case "update" -> Values.toJson(variable.update(remote), labels);
            case "getAndUpdate" -> Values.toJson(variable.getAndUpdate(remote), labels);
            default -> throw new IllegalArgumentException("no shared request " + op);
        };
    }

    /**
     * A deployed agent's store into an element of the array a shared variable holds, which it made in
     * its copy of the array, made in the mission's, the owner's, which the others read; returns the
     * element. Not atomic, as in-process (MASL §7 locks writes of the variable, not of its elements).
     */
    private static Object storeElement(Object array, JsonNode path, JsonNode value, Class<?> type,
            List<AgentImplementation> agents) {
        Object inner = array;
        Class<?> element = type;
        for (int level = 0; level < path.size() - 1; level++) {
            inner = Array.get(inner, path.get(level).intValue());
            element = element.getComponentType();
        }
        Object stored = Values.fromJson(value, agents, Values.NONE, element.getComponentType());
        Array.set(inner, path.get(path.size() - 1).intValue(), stored);
        return stored;
    }

    private static JsonNode entry(Entry entry, String op, int n) {
        return switch (op) {
            case "count" -> JsonNodeFactory.instance.numberNode(entry.count());
            case "getActiveCount" -> JsonNodeFactory.instance.numberNode(entry.getActiveCount());
            case "getWaitingInCount" -> JsonNodeFactory.instance.numberNode(entry.getWaitingInCount());
            case "getWaitingOutCount" -> JsonNodeFactory.instance.numberNode(entry.getWaitingOutCount());
            case "getLockPolicy" -> text(entry.getLockPolicy());
            case "lock" -> {
                entry.lock();
                yield null;
            }
            case "release" -> {
                entry.release(n);
                yield null;
            }
            case "getList" -> ids(entry.getList());
            case "getActiveList" -> ids(entry.getActiveList());
            case "getWaitingInList" -> ids(entry.getWaitingInList());
            case "getWaitingOutList" -> ids(entry.getWaitingOutList());
            default -> throw new IllegalArgumentException("no entry request " + op);
        };
    }

    private static JsonNode ids(List<AgentImplementation> agents) {
        ArrayNode ids = JsonNodeFactory.instance.arrayNode();
        agents.forEach(agent -> ids.add(AgentImplementation.proxyIdOf(agent)));
        return ids;
    }

    private AgentImplementation agent(JsonNode request, String field) {
        int proxyId = request.get(field).intValue();
        return proxyId < 0 ? null : coordination.agents().get(proxyId);
    }

    private static String text(JsonNode request, String field) {
        return request.get(field).textValue();
    }

    private static JsonNode text(String value) {
        return value == null ? NullNode.getInstance() : TextNode.valueOf(value);
    }

    private static JsonNode bool(boolean value) {
        return BooleanNode.valueOf(value);
    }
}
