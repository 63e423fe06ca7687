package masl.runtime.descriptor;

import java.util.List;

/**
 * A primitive (public method) as its descriptor declares it ({@code <Primitive>}).
 *
 * @param memberId       the id permeability states use; a redefinition keeps the id of what it redefines
 * @param returnType     normalised Java type name: {@code int.class} is {@code int}, {@code void},
 *                       {@code java.lang.String}, {@code int[]}, class names as written
 * @param synchronous    {@code synchronous_call}: the caller waits for the result (MASL §9)
 * @param accessor       zero duration, no barrier after it (MASL §5); false when not written
 * @param countermeasure the name of the primitive that undoes this one, or null (MASL §9)
 * @param exceptions     the exception class names, in order
 * @param line           1-based line of the {@code <Primitive>} element in its descriptor
 * @param column         1-based column of that element's {@code <}
 */
public record Primitive(String name, String memberId, String returnType, List<Parameter> parameters,
        boolean synchronous, boolean accessor, String countermeasure, boolean isStatic, boolean isFinal,
        List<String> exceptions, int line, int column) {

    public Primitive {
        parameters = List.copyOf(parameters);
        exceptions = List.copyOf(exceptions);
    }

    /** The Java-like signature, e.g. {@code int getProximity(int)}, for messages. */
    public String signature() {
        return returnType + " " + name + "(" + String.join(", ", parameters.stream().map(Parameter::type).toList())
                + ")";
    }
}
