package masl.jade.outside;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import jade.lang.acl.ACLMessage;
import java.lang.reflect.Field;
import java.util.Optional;
import masl.jade.PrimitiveTable;
import masl.jade.acl.AclInvocations;
import masl.jade.acl.ContentException;
import masl.jade.acl.JsonContent;
import masl.jade.acl.Reply;
import masl.runtime.AgentImplementation;
import masl.runtime.Mission;
import masl.runtime.descriptor.Attribute;

/**
 * A FIPA agent reading a MASL agent's attribute (MASL §9) with a {@code QUERY_REF}, content
 * {@code {"attribute": "battery"}}: {@code INFORM {"result": 80}} if the agent's current permeability
 * state gives others the r bit on it, else {@code REFUSE {"reason": …}} (MASL §11, as a denied read by
 * another agent); {@code NOT_UNDERSTOOD} for malformed content or an attribute the type does not
 * declare. The read is immediate, as MASL's attribute reads are.
 *
 * <p>Public for {@code MaslJadeAgent}, which hands it outsiders' {@code QUERY_REF}s.
 */
public final class AttributeQueries {

    private static final ObjectMapper JSON = new ObjectMapper();

    private AttributeQueries() {
    }

    public static ACLMessage answer(ACLMessage query, Mission mission, int proxyId, PrimitiveTable table,
            AgentImplementation implementation, String agent) {
        String name;
        try {
            name = attributeName(query.getContent());
        } catch (ContentException problem) {
            return AclInvocations.notUnderstood(query, problem);
        }
        Optional<Attribute> attribute = table.type().findAttribute(name);
        if (attribute.isEmpty()) {
            return AclInvocations.notUnderstood(query, new ContentException(agent + " (" + table.type().shortName()
                    + ") has no attribute " + name, 1, 1));
        }
        if (!mission.othersMayRead(proxyId, name)) {
            return AclInvocations.reply(query, Reply.Kind.REFUSED, JsonContent.refusal("the permeability of " + agent
                    + " denies others reading " + name));
        }
        try {
            Field field = implementation.getClass().getField(name);
            return AclInvocations.reply(query, Reply.Kind.RESULT,
                    JsonContent.result(field.get(attribute.get().isStatic() ? null : implementation)));
        } catch (ReflectiveOperationException | RuntimeException unreadable) {
            return AclInvocations.reply(query, Reply.Kind.FAILED, JsonContent.failure(unreadable));
        }
    }

    private static String attributeName(String content) throws ContentException {
        JsonNode node;
        try {
            node = JSON.readTree(content == null ? "" : content);
        } catch (JsonProcessingException malformed) {
            throw new ContentException("malformed JSON: " + malformed.getOriginalMessage().lines().findFirst()
                    .orElse(""), 1, 1);
        }
        if (node == null || !node.isObject() || node.size() != 1 || !node.path("attribute").isTextual()) {
            throw new ContentException("expected {\"attribute\": name}", 1, 1);
        }
        return node.get("attribute").asText();
    }
}
