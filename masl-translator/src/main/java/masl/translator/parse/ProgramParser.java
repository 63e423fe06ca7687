package masl.translator.parse;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.function.BooleanSupplier;
import masl.grammar.MASLLexer;
import masl.grammar.MASLParser;
import masl.grammar.MaslRuleContext;
import masl.translator.diagnostics.Diagnostics;
import masl.translator.source.SourceFile;
import org.antlr.v4.runtime.BailErrorStrategy;
import org.antlr.v4.runtime.BaseErrorListener;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.CommonTokenStream;
import org.antlr.v4.runtime.InputMismatchException;
import org.antlr.v4.runtime.ListTokenSource;
import org.antlr.v4.runtime.Parser;
import org.antlr.v4.runtime.RecognitionException;
import org.antlr.v4.runtime.Recognizer;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.Vocabulary;
import org.antlr.v4.runtime.atn.PredictionMode;
import org.antlr.v4.runtime.misc.IntervalSet;
import org.antlr.v4.runtime.misc.ParseCancellationException;

/**
 * Parses a MASL program with the ANTLR grammar and turns every syntax error into a positioned
 * {@link masl.runtime.diagnostic.Diagnostic} in the user's words. Every syntax error of a file
 * is reported in one run, each once: {@link TokenRepairs} first reports and repairs the mistakes a
 * reader sees at a glance (a misspelt keyword, a Java habit, a brace missing by the indentation), then
 * ANTLR's recovery ({@link RecoveryStrategy}) goes on after each remaining error.
 */
public final class ProgramParser {

    /**
     * The parse tree and the token stream it was built from (the analysis reads path texts from it).
     *
     * @param nodes how many rule nodes the tree has, numbered 0 to {@code nodes - 1} ({@link MaslRuleContext})
     * @param repaired whether the tree holds repairs the analysis must not see (a guess after a syntax
     *     error, a literal Java would not read): false for a program without syntax errors, or whose
     *     every error was repaired as the user meant ({@link RecoveryStrategy}); {@code tree} is null if
     *     the program was not parsed at all (nested too deeply, {@link Nesting})
     * @param constantProblems the constants javac would refuse ({@link ConstantLimits}), for the analysis
     *     to report
     */
    public record Parsed(SourceFile source, MASLParser.ProgramContext tree, CommonTokenStream tokens, int nodes,
            boolean repaired, List<ConstantLimits.Problem> constantProblems) { }

    private ProgramParser() {
    }

    /**
     * Whether a repair after a syntax error put {@code token} in, the user having left it out (the
     * {@code local} of {@code String s = "x";}, reported with the declaration's other mistakes).
     */
    public static boolean wasLeftOut(Token token) {
        return TokenRepairs.wasLeftOut(token);
    }

    /**
     * Parses in ANTLR's fast SLL mode first, giving up at the first error; only a program that
     * fails there is parsed again in full LL mode, which reports every error (ANTLR's two-stage
     * parsing: SLL accepts the same valid programs of this grammar with the same tree, much faster).
     */
    public static Parsed parse(SourceFile source, Diagnostics diagnostics) {
        MASLLexer lexer = new MASLLexer(CharStreams.fromString(source.text(), source.name()));
        lexer.removeErrorListeners();
        CommonTokenStream tokens = new CommonTokenStream(lexer);
        tokens.fill();
        if (Nesting.reportTooDeep(source.name(), tokens.getTokens(), diagnostics)) {
            return new Parsed(source, null, tokens, 0, true, List.of());
        }
        MASLParser parser = new MASLParser(tokens);
        parser.removeErrorListeners();
        parser.getInterpreter().setPredictionMode(PredictionMode.SLL);
        parser.setErrorHandler(new BailErrorStrategy());
        Parsed parsed;
        try {
            parsed = numbered(source, parser, tokens, () -> false);
        } catch (ParseCancellationException notSll) {
            TokenRepairs.Repaired repaired = TokenRepairs.repair(source.name(), tokens.getTokens(), diagnostics);
            tokens = new CommonTokenStream(new ListTokenSource(repaired.tokens(), source.name()));
            tokens.fill();
            parser.setTokenStream(tokens);
            parser.getInterpreter().setPredictionMode(PredictionMode.LL);
            RecoveryStrategy recovery = new RecoveryStrategy();
            parser.setErrorHandler(recovery);
            parser.addErrorListener(new Reporter(source.name(), diagnostics, repaired.reported()));
            parsed = numbered(source, parser, tokens, () -> !(repaired.sound() && recovery.isSound()));
        }
        if (!checkLiterals(source.name(), tokens, diagnostics)) {
            // The analysis reads the literals' values: one Java would not read has none.
            return new Parsed(source, parsed.tree(), parsed.tokens(), parsed.nodes(), true, parsed.constantProblems());
        }
        return parsed;
    }

    /**
     * Reports each string or character literal Java would not read as it shows ({@link Literals}), at
     * the escape at fault: the generated Java holds the literals' values, and must hold exactly what
     * the analysis saw.
     */
    private static boolean checkLiterals(String file, CommonTokenStream tokens, Diagnostics diagnostics) {
        boolean readable = true;
        tokens.fill();
        for (Token token : tokens.getTokens()) {
            try {
                if (token.getType() == MASLLexer.StringLiteral) {
                    Literals.string(token.getText());
                } else if (token.getType() == MASLLexer.CharacterLiteral) {
                    Literals.character(token.getText());
                }
            } catch (Literals.Problem problem) {
                String text = token.getText();
                diagnostics.error(file, token.getLine(),
                        token.getCharPositionInLine() + 1 + text.codePointCount(0, problem.offset()),
                        problem.getMessage());
                readable = false;
            }
        }
        return readable;
    }

    /**
     * The program's tree, its nodes numbered as they are built; {@code repaired} says, once it is
     * parsed, whether repairs the analysis must not see were made.
     */
    private static Parsed numbered(SourceFile source, MASLParser parser, CommonTokenStream tokens,
            BooleanSupplier repaired) {
        MaslRuleContext.Numbering numbering = new MaslRuleContext.Numbering();
        ConstantLimits constants = new ConstantLimits();
        parser.removeParseListeners();
        parser.addParseListener(numbering);
        parser.addParseListener(constants);
        MASLParser.ProgramContext tree = parser.program();
        return new Parsed(source, tree, tokens, numbering.count(), repaired.getAsBoolean(), constants.problems());
    }

    /** Rewords ANTLR's messages: which token was found, and what was expected when that is short. */
    private static final class Reporter extends BaseErrorListener {
        private static final int MAX_LISTED = 4;
        private final String file;
        private final Diagnostics diagnostics;
        private final Set<TokenRepairs.Position> repaired;
        private int lastErrorLine;

        Reporter(String file, Diagnostics diagnostics, Set<TokenRepairs.Position> repaired) {
            this.file = file;
            this.diagnostics = diagnostics;
            this.repaired = repaired;
        }

        @Override
        public void syntaxError(Recognizer<?, ?> recognizer, Object offendingSymbol, int line, int column,
                String antlrMessage, RecognitionException error) {
            Parser parser = (Parser) recognizer;
            Token found = (Token) offendingSymbol;
            // ANTLR's recovery often trips again on the tokens right after an error: one error a line
            // keeps those echoes out and still reports unrelated errors of the file.
            if (line == lastErrorLine) {
                return;
            }
            lastErrorLine = line;
            IntervalSet expected = parser.getExpectedTokens();
            if (antlrMessage.startsWith("missing ") && closes(expected)) {
                Token previous = previousToken(parser, found);
                if (previous != null) {
                    report(previous.getLine(), endColumn(previous), "expected " + describe(expected, parser.getVocabulary()));
                    return;
                }
            }
            if (found.getType() == MASLLexer.UnterminatedString) {
                report(line, column + 1, "unterminated string literal");
                return;
            }
            boolean declaration = found.getType() == MASLLexer.LOCAL || found.getType() == MASLLexer.SHARED;
            if (declaration && parser.getContext() instanceof MASLParser.ProgramContext) {
                // A global variable, as in Java's fields: MASL's variables belong to blocks.
                report(line, column + 1, "unexpected '" + found.getText() + "': variables are declared at the head of"
                        + " an entry block, `" + found.getText() + "` for " + (found.getType() == MASLLexer.SHARED
                                ? "one the block's members share" : "each agent's own")
                        + ": `synchronous entry main (true) { " + found.getText() + " int x = 0; … }`");
                return;
            }
            if (found.getType() == MASLLexer.COMMA && parser.getContext() instanceof MASLParser.VariableDeclContext) {
                // Java's habit, `int i = 0, j = 1;`: in MASL the one initialiser follows every name.
                report(line, column + 1, "unexpected ',': a declaration's names come before its one initial value"
                        + " (`local int a, b = 0;`); give other values in declarations of their own");
                return;
            }
            String message = "unexpected " + describe(found);
            boolean listable = expected.size() > 0 && expected.size() <= MAX_LISTED
                    && (error == null || error instanceof InputMismatchException);
            if (listable) {
                message += ", expected " + describe(expected, parser.getVocabulary());
            }
            report(line, column + 1, message);
        }

        /** An error, unless the repairs reported a mistake there already. */
        private void report(int line, int column, String message) {
            if (!repaired.contains(new TokenRepairs.Position(line, column))) {
                diagnostics.error(file, line, column, message);
            }
        }

        /** A missing ';' or closing bracket belongs after the previous token, as javac reports it. */
        private static boolean closes(IntervalSet expected) {
            if (expected.size() != 1) {
                return false;
            }
            int type = expected.getMinElement();
            return type == MASLLexer.SEMI || type == MASLLexer.RPAREN || type == MASLLexer.RBRACE
                    || type == MASLLexer.RBRACK;
        }

        private static Token previousToken(Parser parser, Token found) {
            for (int i = found.getTokenIndex() - 1; i >= 0; i--) {
                Token token = parser.getTokenStream().get(i);
                if (token.getChannel() == Token.DEFAULT_CHANNEL) {
                    return token;
                }
            }
            return null;
        }

        /** The column just after a token, where a missing ';' belongs. */
        private static int endColumn(Token token) {
            String text = token.getText();
            int lastBreak = Math.max(text.lastIndexOf('\n'), text.lastIndexOf('\r'));
            return lastBreak < 0 ? token.getCharPositionInLine() + text.length() + 1 : text.length() - lastBreak;
        }

        private static String describe(Token token) {
            if (token.getType() == Token.EOF) {
                return "end of file";
            }
            return "'" + token.getText() + "'";
        }

        private static String describe(IntervalSet expected, Vocabulary vocabulary) {
            List<String> names = new ArrayList<>();
            for (int type : expected.toArray()) {
                // `extends` and `super` are names in MASL (§2): "a name" covers them.
                boolean nameWord = type == MASLLexer.EXTENDS_WORD || type == MASLLexer.SUPER_WORD;
                String name = tokenName(type, vocabulary);
                if (!(nameWord && expected.contains(MASLLexer.Identifier)) && !names.contains(name)) {
                    names.add(name);
                }
            }
            if (names.size() == 1) {
                return names.get(0);
            }
            return String.join(", ", names.subList(0, names.size() - 1)) + " or " + names.get(names.size() - 1);
        }

        private static String tokenName(int type, Vocabulary vocabulary) {
            if (type == Token.EOF) {
                return "end of file";
            }
            String literal = vocabulary.getLiteralName(type);
            if (literal != null) {
                return literal;
            }
            return switch (vocabulary.getSymbolicName(type)) {
                case "Identifier" -> "a name";
                case "IntegerLiteral" -> "an integer";
                case "FloatingPointLiteral" -> "a number";
                case "StringLiteral" -> "a string";
                case "CharacterLiteral" -> "a character";
                default -> vocabulary.getDisplayName(type);
            };
        }

    }
}
