package masl.jade.acl;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import java.util.ArrayList;
import java.util.List;

/**
 * The content of the coordinator's {@code REQUEST} (conversation {@code masl-place}) asking a
 * container to host the bodies of the agents placed on it:
 * <pre>
 * {"agents": [{"name": "w1", "proxyId": 1, "class": "masl.agents.Default"}, …]}
 * </pre>
 */
public final class PlacementContent {

    /** One body to host: the MASL agent's name (its JADE agent's), proxy id and implementation class. */
    public record Body(String name, int proxyId, String className) {
    }

    private static final ObjectMapper MAPPER = new ObjectMapper();
    private static final JsonNodeFactory NODES = JsonNodeFactory.instance;

    private PlacementContent() {
    }

    public static String write(List<Body> bodies) {
        ArrayNode agents = NODES.arrayNode();
        for (Body body : bodies) {
            agents.addObject().put("name", body.name()).put("proxyId", body.proxyId()).put("class", body.className());
        }
        return NODES.objectNode().set("agents", agents).toString();
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
