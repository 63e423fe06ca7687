package masl.jade.deployment;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import masl.runtime.AgentImplementation;
import masl.runtime.descriptor.AgentType;

/**
 * The agents' objects in a container of deployed programs. An agent this container runs has its real
 * object, whose primitives and attributes the mission may ask for by name ({@link #answer}). Any other
 * agent runs elsewhere (in the mission's JVM, in another container) and has a {@link Recording} stub
 * here: a program's invocation of it, or access to its attributes, goes to the mission as the
 * member's name and values, never as the code the program made, and runs on its real object.
 */
final class TeamMembers {

    private final Map<Integer, Members> hosted = new ConcurrentHashMap<>();
    private final Map<Integer, Members> elsewhere = new ConcurrentHashMap<>();

    /** The object of agent {@code proxyId} of type {@code type} here, given the one {@code made} of its class. */
    AgentImplementation implementation(int proxyId, AgentType type, AgentImplementation made, boolean runsHere) {
        if (type == null) {
            return made;
        }
        Members members = new Members(type, made.getClass());
        if (runsHere) {
            hosted.put(proxyId, members);
            return made;
        }
        elsewhere.put(proxyId, members);
        return Members.STUBS.instantiate(made.getClass(), members.methods(), new Recording(members.methods()));
    }

    /** Whether agent {@code proxyId} runs elsewhere and its type has {@code primitive}: a call that names it. */
    boolean invokedByName(int proxyId, String primitive) {
        Members members = elsewhere.get(proxyId);
        return members != null && members.declares(primitive);
    }

    /** Whether agent {@code proxyId} runs elsewhere: its attributes are read and written by name. */
    boolean accessedByName(int proxyId) {
        return elsewhere.containsKey(proxyId);
    }

    /**
     * The value (tagged) that {@code write}, a program's write of {@code attribute} of {@code owner}
     * (an agent that runs elsewhere), writes, found on {@code owner}'s stub here ({@link Members#written}).
     */
    JsonNode written(int proxyId, AgentImplementation owner, String attribute, Runnable write) {
        return Values.toJson(elsewhere.get(proxyId).written(owner, attribute, write));
    }

    /**
     * Runs the mission's {@code primitive}, {@code read} or {@code write} request on {@code target},
     * the real object of agent {@code proxyId}, which runs here: the answer, with the value (tagged)
     * of a primitive or a read.
     */
    ObjectNode answer(int proxyId, AgentImplementation target, ObjectNode request, List<? extends AgentImplementation> agents) {
        Members members = hosted.get(proxyId);
        if (members == null) {
            throw new IllegalArgumentException("agent " + proxyId + " has no type whose members a call may name");
        }
        ObjectNode answer = JsonNodeFactory.instance.objectNode().put("outcome", "ran");
        String attribute = request.path("attribute").asText();
        switch (request.path("kind").asText()) {
            case "primitive" -> {
                List<Object> args = new ArrayList<>();
                request.path("args").forEach(arg -> args.add(Values.fromJson(arg, agents)));
                answer.set("value", Values.toJson(members.invoke(target, request.path("primitive").asText(), args)));
            }
            case "read" -> answer.set("value", Values.toJson(members.read(target, attribute)));
            case "write" -> members.write(target, attribute, Values.fromJson(request.get("value"), agents));
            default -> throw new IllegalArgumentException("not a request for a member: " + request);
        }
        return answer;
    }
}
