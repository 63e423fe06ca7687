package masl.jade.acl;

import com.fasterxml.jackson.databind.JsonNode;

/** The answer to an invocation request, by performative. */
public sealed interface Reply {

    /** Which answer a reply is: INFORM, REFUSE, FAILURE or NOT_UNDERSTOOD. */
    enum Kind { RESULT, REFUSED, FAILED, NOT_UNDERSTOOD }

    /** {@code INFORM}: the primitive ran; {@code value} is its result ({@code null} for {@code void}). */
    record Result(JsonNode value) implements Reply {
    }

    /** {@code REFUSE}: permeability denied the invocation; the primitive did not run. */
    record Refused(String reason) implements Reply {
    }

    /** {@code FAILURE}: the primitive threw {@code exception} (a class name) with {@code message}. */
    record Failed(String exception, String message) implements Reply {
    }

    /** {@code NOT_UNDERSTOOD}: the request was malformed or unknown; {@code error} says why. */
    record NotUnderstood(String error) implements Reply {
    }
}
