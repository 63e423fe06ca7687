package masl.jade.acl;

import java.util.List;

/** The content of an invocation {@code REQUEST}: {@code {"primitive": name, "args": [ … ]}}. */
public record InvocationRequest(String primitive, List<Argument> args) {

    public InvocationRequest {
        args = List.copyOf(args);
    }
}
