package masl.lsp;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import masl.grammar.MASLLexer;
import masl.runtime.descriptor.AgentType;
import org.antlr.v4.runtime.Token;

/**
 * What stands before a {@code .}: the current agent ({@code .m()}, {@code this.m()}, {@code l.this.m()}), an
 * agent of a known type ({@code a.m()}, {@code l.a.m()}, a variable of an agent type), an entry
 * ({@code work.count}), a label ({@code l.isFinished()}) or something the editor does not follow (a Java
 * object), judged from the tokens alone so that it works while the line is being typed.
 */
sealed interface Receiver {

    /** The current agent: any of the program's agent types (MASL §4). */
    record Self() implements Receiver { }

    /** An agent declared with {@code typeName}. */
    record Agent(String typeName) implements Receiver { }

    /** An entry name before an entry member (MASL §6.7). */
    record Entry(String name) implements Receiver { }

    /** A label before a label member or a primitive it launches (MASL §10). */
    record Label(ProgramIndex.Declared label) implements Receiver { }

    /** A Java value, a literal, a call's result: nothing the descriptors describe. */
    record Unknown() implements Receiver { }

    /**
     * The receiver of the member after the {@code .} at {@code dot} in {@code tokens} (the default channel's
     * tokens), names resolved in {@code scope}.
     */
    static Receiver before(List<Token> tokens, int dot, ProgramIndex index, ProgramIndex.Block scope) {
        Token previous = dot > 0 ? tokens.get(dot - 1) : null;
        if (previous == null || previous.getType() == MASLLexer.THIS) {
            return new Self();
        }
        if (previous.getType() == MASLLexer.RBRACK) {
            return elementOf(tokens, dot - 1, index, scope);
        }
        if (!isName(previous)) {
            boolean startsAnExpression = previous.getType() != MASLLexer.RPAREN && previous.getType() != MASLLexer.RBRACK
                    && !isLiteral(previous);
            return startsAnExpression ? new Self() : new Unknown();
        }
        String name = previous.getText();
        boolean qualified = dot >= 3 && tokens.get(dot - 2).getType() == MASLLexer.DOT;
        if (qualified) {
            Receiver outer = before(tokens, dot - 2, index, scope);
            return outer instanceof Label ? agentNamed(name, index, scope) : new Unknown();
        }
        Optional<ProgramIndex.Declared> declared = index.lookup(name, scope);
        if (declared.isPresent()) {
            return switch (declared.get().kind()) {
                case LABEL -> new Label(declared.get());
                case VARIABLE -> index.types().containsKey(declared.get().typeName())
                        ? new Agent(declared.get().typeName()) : new Unknown();
                case EVENT -> new Unknown();
            };
        }
        if (index.agent(name).isPresent()) {
            return agentNamed(name, index, scope);
        }
        return index.hasEntryMembers(name) || index.block(name).isPresent() ? new Entry(name) : new Unknown();
    }

    /** {@code team[i].}: an element of a variable of an agent array type. */
    private static Receiver elementOf(List<Token> tokens, int closing, ProgramIndex index, ProgramIndex.Block scope) {
        int depth = 0;
        for (int i = closing; i >= 0; i--) {
            int type = tokens.get(i).getType();
            depth += type == MASLLexer.RBRACK ? 1 : type == MASLLexer.LBRACK ? -1 : 0;
            if (depth == 0) {
                if (i == 0 || !isName(tokens.get(i - 1))) {
                    return new Unknown();
                }
                return index.lookup(tokens.get(i - 1).getText(), scope)
                        .filter(declared -> declared.typeName() != null && declared.typeName().endsWith("[]"))
                        .map(declared -> declared.typeName().substring(0, declared.typeName().length() - 2).strip())
                        .filter(index.types()::containsKey)
                        .<Receiver>map(Agent::new).orElse(new Unknown());
            }
        }
        return new Unknown();
    }

    private static Receiver agentNamed(String name, ProgramIndex index, ProgramIndex.Block scope) {
        Optional<ProgramIndex.Declared> variable = index.lookup(name, scope)
                .filter(declared -> declared.kind() == ProgramIndex.Kind.VARIABLE);
        if (variable.isPresent()) {
            return index.types().containsKey(variable.get().typeName()) ? new Agent(variable.get().typeName())
                    : new Unknown();
        }
        return index.agent(name).<Receiver>map(agent -> new Agent(agent.typeName())).orElse(new Unknown());
    }

    /** The agent types whose primitives and attributes the receiver has, by MASL name; empty for the others. */
    static Map<String, AgentType> agentTypes(Receiver receiver, ProgramIndex index) {
        Map<String, AgentType> types = new LinkedHashMap<>();
        if (receiver instanceof Self || receiver instanceof Label) {
            index.loadedTypes().forEach(type -> types.put(type.name(), type.descriptor()));
        } else if (receiver instanceof Agent agent) {
            ProgramIndex.TypeDef type = index.types().get(agent.typeName());
            if (type != null && type.descriptor() != null) {
                types.put(type.name(), type.descriptor());
            }
        }
        return types;
    }

    static boolean isName(Token token) {
        int type = token.getType();
        return type == MASLLexer.Identifier || type == MASLLexer.EXTENDS_WORD || type == MASLLexer.SUPER_WORD;
    }

    private static boolean isLiteral(Token token) {
        int type = token.getType();
        return type == MASLLexer.StringLiteral || type == MASLLexer.IntegerLiteral
                || type == MASLLexer.FloatingPointLiteral || type == MASLLexer.CharacterLiteral
                || type == MASLLexer.TRUE || type == MASLLexer.FALSE || type == MASLLexer.NULL;
    }
}
