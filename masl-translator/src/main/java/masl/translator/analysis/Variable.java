package masl.translator.analysis;

import java.util.Objects;
import masl.grammar.MASLParser;

/**
 * A variable declared in a block (MASL §7). {@code local int a, b = 0;} declares two variables that
 * share the one initialiser: each is initialised with it.
 *
 * @param name the name
 * @param type its type
 * @param sharing one copy per member or per wave
 * @param isFinal whether it is {@code final}
 * @param limitedTo the type that alone may write it ({@code limited(T)}), or null
 * @param initializer the initialiser's parse tree, or null for the type's default value
 * @param block the declaring block
 */
public record Variable(String name, MaslType type, Sharing sharing, boolean isFinal, ImportedType limitedTo,
        MASLParser.VariableInitializerContext initializer, Block block) implements Symbol {

    @Override
    public String toString() {
        return "variable " + name;
    }

    // equals and hashCode written out, here and in the types (ImportedType, MaslType): a record's own go
    // through invokedynamic and method handles, slow in the interpreter of the fresh JVM `masl run` translates in.
    @Override
    public boolean equals(Object o) {
        return o instanceof Variable v && name.equals(v.name) && type.equals(v.type) && sharing == v.sharing
                && isFinal == v.isFinal && Objects.equals(limitedTo, v.limitedTo) && initializer == v.initializer
                && block == v.block;
    }

    @Override
    public int hashCode() {
        return name.hashCode() * 31 + System.identityHashCode(block);
    }
}
