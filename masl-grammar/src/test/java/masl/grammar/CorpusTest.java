package masl.grammar;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.antlr.v4.runtime.BaseErrorListener;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.CommonTokenStream;
import org.antlr.v4.runtime.RecognitionException;
import org.antlr.v4.runtime.Recognizer;
import org.antlr.v4.runtime.tree.ParseTree;
import org.antlr.v4.runtime.tree.ParseTreeWalker;
import org.antlr.v4.runtime.tree.TerminalNode;
import org.antlr.v4.runtime.tree.ErrorNode;
import org.antlr.v4.runtime.tree.ParseTreeListener;
import org.antlr.v4.runtime.ParserRuleContext;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/** Every program of the corpus (the examples of examples.md and programs written for the grammar) parses. */
class CorpusTest {

    static final List<String> CORPUS = List.of(
            "e1-scalar-main.masl",
            "e2-shared-and-local-variables-in-lock-step.masl",
            "e3-asynchronous-child-inside-a-synchronous-parent.masl",
            "e4-events-lookup-in-the-parent-resume.masl",
            "e5-permeability-a-denied-invocation-becomes-timeout.masl",
            "e6-one-at-a-time-through-a-locked-synchronous-block.masl",
            "e7-reelect-a-wave-that-thins-out.masl",
            "e8-break-out-of-two-blocks.masl",
            "every-production.masl");

    static Stream<String> corpus() {
        return CORPUS.stream();
    }

    @ParameterizedTest
    @MethodSource("corpus")
    void parsesWithoutSyntaxErrors(String name) throws IOException {
        Parsed parsed = Parsed.of(read(name));
        assertEquals(List.of(), parsed.errors, name);
    }

    @Test
    void theCorpusUsesEveryParserAlternative() throws IOException {
        List<String> unused = new ArrayList<>(Alternatives.all());
        for (String name : CORPUS) {
            unused.removeAll(Alternatives.used(Parsed.of(read(name)).tree));
        }
        assertEquals(List.of(), unused, "parser rules or labelled alternatives no corpus program uses");
    }

    static String read(String name) throws IOException {
        try (InputStream in = CorpusTest.class.getResourceAsStream("/corpus/" + name)) {
            assertTrue(in != null, "missing corpus file " + name);
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    /** A parse of one source text, with the syntax errors ANTLR reported. */
    static final class Parsed {
        final List<String> errors = new ArrayList<>();
        ParseTree tree;

        static Parsed of(String source) {
            Parsed parsed = new Parsed();
            MASLLexer lexer = new MASLLexer(CharStreams.fromString(source));
            MASLParser parser = new MASLParser(new CommonTokenStream(lexer));
            BaseErrorListener collect = new BaseErrorListener() {
                @Override
                public void syntaxError(Recognizer<?, ?> r, Object symbol, int line, int col, String msg, RecognitionException e) {
                    parsed.errors.add(line + ":" + (col + 1) + ": " + msg);
                }
            };
            lexer.removeErrorListeners();
            parser.removeErrorListeners();
            lexer.addErrorListener(collect);
            parser.addErrorListener(collect);
            parsed.tree = parser.program();
            return parsed;
        }
    }

    /** The parser's rules and labelled alternatives, by the context class ANTLR generates for each. */
    static final class Alternatives {
        static List<String> all() {
            List<String> names = new ArrayList<>();
            for (Class<?> type : MASLParser.class.getDeclaredClasses()) {
                boolean labelledParent = type.getSuperclass() != MaslRuleContext.class
                        && ParserRuleContext.class.isAssignableFrom(type.getSuperclass());
                boolean hasLabelledChildren = false;
                for (Class<?> other : MASLParser.class.getDeclaredClasses()) {
                    hasLabelledChildren |= other.getSuperclass() == type;
                }
                if (ParserRuleContext.class.isAssignableFrom(type) && (labelledParent || !hasLabelledChildren)) {
                    names.add(type.getSimpleName());
                }
            }
            return names;
        }

        static List<String> used(ParseTree tree) {
            List<String> names = new ArrayList<>();
            ParseTreeWalker.DEFAULT.walk(new ParseTreeListener() {
                @Override public void enterEveryRule(ParserRuleContext ctx) { names.add(ctx.getClass().getSimpleName()); }
                @Override public void exitEveryRule(ParserRuleContext ctx) { }
                @Override public void visitTerminal(TerminalNode node) { }
                @Override public void visitErrorNode(ErrorNode node) { }
            }, tree);
            return names;
        }
    }
}
