package masl.translator.analysis;

import org.antlr.v4.runtime.Token;

/** What the receiver of a member ({@code receiver.member}) turned out to be. */
sealed interface Receiver {
    /** A value: a variable, an agent, {@code this}, any expression. */
    record Value(MaslType type) implements Receiver { }

    record OfLabel(Label label) implements Receiver { }

    record OfEntry(EntryRef entry) implements Receiver { }

    /** A class or an agent type, for its static members. */
    record OfType(MaslType type) implements Receiver { }

    /** Names that may begin a qualified class name ({@code java.util}); {@code first} is reported if not. */
    record PackagePrefix(String prefix, Token first) implements Receiver { }
}
