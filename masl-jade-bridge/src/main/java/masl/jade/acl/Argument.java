package masl.jade.acl;

import com.fasterxml.jackson.databind.JsonNode;

/** One argument of an invocation request as JSON, with where it starts in the content (1-based). */
public record Argument(JsonNode value, int line, int column) {
}
