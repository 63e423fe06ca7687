package masl.jade.acl;

import java.util.List;

/**
 * The content of an invocation {@code REQUEST}: {@code {"primitive": name, "args": [ … ]}}, with
 * where the primitive's name starts in the content (1-based line and column).
 */
public record InvocationRequest(String primitive, int line, int column, List<Argument> args) {

    public InvocationRequest {
        args = List.copyOf(args);
    }
}
