package masl.translator.analysis;

/** A type named in an expression, as the receiver of a static member: {@code Math.max}, {@code String.class}. */
public record TypeRef(MaslType type) implements Symbol {
}
