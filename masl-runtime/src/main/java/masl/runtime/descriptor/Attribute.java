package masl.runtime.descriptor;

/**
 * An attribute (public field) as its descriptor declares it ({@code <Attribute>}).
 *
 * @param memberId the id permeability states use; a redefinition keeps the id of what it redefines
 * @param type     normalised Java type name (see {@link Primitive#returnType()})
 * @param value    the initial value as written (a constant's value), or null
 * @param line     1-based line of the {@code <Attribute>} element in its descriptor
 * @param column   1-based column of that element's {@code <}
 */
public record Attribute(String name, String memberId, String type, String value, boolean isStatic,
        boolean isFinal, int line, int column) {
}
