package masl.runtime.descriptor;

/**
 * A primitive's parameter.
 *
 * @param type normalised Java type name (see {@link Primitive#returnType()})
 */
public record Parameter(String name, String type) {
}
