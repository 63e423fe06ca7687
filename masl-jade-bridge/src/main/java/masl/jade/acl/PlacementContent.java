package masl.jade.acl;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;

/**
 * The content of the coordinator's {@code REQUEST} (conversation {@code masl-place}) asking a
 * container to host the bodies of the agents placed on it:
 * <pre>
 * {"agents": [{"name": "w1", "proxyId": 1, "class": "masl.agents.Default"}, …]}
 * </pre>
 * and, if the container is to run deployed agents' programs, what they are made from (MASL text, never
 * code): {@code "deploy": {"agents": ["a"], "program": "e2.masl", "text": "…", "descriptors": {"R.xml":
 * "…"}, "key": "…"}}.
 */
public final class PlacementContent {

    /** One body to host: the MASL agent's name (its JADE agent's), proxy id and implementation class. */
    public record Body(String name, int proxyId, String className) {
    }

    private static final ObjectMapper MAPPER = new ObjectMapper();
    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;

    private PlacementContent() {
    }

    /** The agents deployed to a container and what their programs are made from. */
    public record Deploy(List<String> agents, String program, String text, Map<String, String> descriptors,
            String key) {
    }

    public static String write(List<Body> bodies) {
        return write(bodies, null);
    }

    /** Bodies, and the deployment ({@code null}: none). */
    public static String write(List<Body> bodies, Deploy deploy) {
        ArrayNode agents = NODES.arrayNode();
        for (Body body : bodies) {
            agents.addObject().put("name", body.name()).put("proxyId", body.proxyId()).put("class", body.className());
        }
        ObjectNode content = NODES.objectNode();
        content.set("agents", agents);
        if (deploy != null) {
            ObjectNode section = content.putObject("deploy");
            deploy.agents().forEach(section.putArray("agents")::add);
            section.put("program", deploy.program()).put("text", deploy.text()).put("key", deploy.key());
            ObjectNode descriptors = section.putObject("descriptors");
            deploy.descriptors().forEach(descriptors::put);
        }
        return content.toString();
    }

    /** The deployment a placement's content carries, if any. @throws ContentException if it is malformed */
    public static Optional<Deploy> readDeploy(String content) throws ContentException {
        JsonNode section;
        try {
            section = MAPPER.readTree(content == null ? "" : content).path("deploy");
        } catch (JsonProcessingException e) {
            throw new ContentException("malformed JSON: " + e.getOriginalMessage(), 1, 1);
        }
        if (section.isMissingNode()) {
            return Optional.empty();
        }
        if (!section.path("agents").isArray() || !section.path("program").isTextual() || !section.path("text").isTextual()
                || !section.path("key").isTextual() || !section.path("descriptors").isObject()) {
            throw new ContentException("a deployment needs agents, program, text, descriptors and key", 1, 1);
        }
        List<String> agents = new ArrayList<>();
        section.get("agents").forEach(agent -> agents.add(agent.asText()));
        Map<String, String> descriptors = new TreeMap<>();
        section.get("descriptors").fields().forEachRemaining(file -> descriptors.put(file.getKey(), file.getValue().asText()));
        return Optional.of(new Deploy(agents, section.get("program").textValue(), section.get("text").textValue(),
                descriptors, section.get("key").textValue()));
    }

    /** @throws ContentException if the content is not such an object */
    public static List<Body> read(String content) throws ContentException {
        JsonNode root;
        try {
            root = MAPPER.readTree(content == null ? "" : content);
        } catch (JsonProcessingException e) {
            throw new ContentException("malformed JSON: " + e.getOriginalMessage(), 1, 1);
        }
        if (root == null || !root.path("agents").isArray()) {
            throw new ContentException("expected {\"agents\": [...]}", 1, 1);
        }
        List<Body> bodies = new ArrayList<>();
        for (JsonNode agent : root.get("agents")) {
            if (!agent.path("name").isTextual() || !agent.path("proxyId").isInt() || !agent.path("class").isTextual()) {
                throw new ContentException("each agent needs a name, a proxyId and a class: " + agent, 1, 1);
            }
            bodies.add(new Body(agent.get("name").textValue(), agent.get("proxyId").intValue(),
                    agent.get("class").textValue()));
        }
        return bodies;
    }
}
