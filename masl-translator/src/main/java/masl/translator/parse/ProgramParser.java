package masl.translator.parse;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import masl.grammar.MASLLexer;
import masl.grammar.MASLParser;
import masl.grammar.MaslRuleContext;
import masl.translator.diagnostics.Diagnostics;
import masl.translator.diagnostics.Suggestions;
import masl.translator.source.SourceFile;
import org.antlr.v4.runtime.BailErrorStrategy;
import org.antlr.v4.runtime.BaseErrorListener;
import org.antlr.v4.runtime.CharStreams;
import org.antlr.v4.runtime.CommonTokenStream;
import org.antlr.v4.runtime.DefaultErrorStrategy;
import org.antlr.v4.runtime.InputMismatchException;
import org.antlr.v4.runtime.Parser;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.RecognitionException;
import org.antlr.v4.runtime.Recognizer;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.Vocabulary;
import org.antlr.v4.runtime.WritableToken;
import org.antlr.v4.runtime.atn.PredictionMode;
import org.antlr.v4.runtime.misc.IntervalSet;
import org.antlr.v4.runtime.misc.ParseCancellationException;
import org.antlr.v4.runtime.tree.ErrorNode;
import org.antlr.v4.runtime.tree.ParseTree;

/**
 * Parses a MASL program with the ANTLR grammar and turns every syntax error into a positioned
 * {@link masl.translator.diagnostics.Diagnostic} in the user's words. ANTLR's recovery goes on
 * after an error, so every syntax error of a file is reported in one run.
 */
public final class ProgramParser {

    /**
     * The parse tree and the token stream it was built from (the analysis reads path texts from it).
     *
     * @param nodes how many rule nodes the tree has, numbered 0 to {@code nodes - 1} ({@link MaslRuleContext})
     * @param repaired whether ANTLR had to repair the tree after syntax errors; then {@code tree} is
     *     null if the program was not parsed at all (nested too deeply, {@link Nesting})
     * @param constantProblems the constants javac would refuse ({@link ConstantLimits}), for the analysis
     *     to report
     */
    public record Parsed(SourceFile source, MASLParser.ProgramContext tree, CommonTokenStream tokens, int nodes,
            boolean repaired, List<ConstantLimits.Problem> constantProblems) { }

    private static final Map<String, Integer> MODES = Map.of("scalar", MASLLexer.SCALAR,
            "synchronous", MASLLexer.SYNCHRONOUS, "asynchronous", MASLLexer.ASYNCHRONOUS);

    private ProgramParser() {
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
            parsed = numbered(source, parser, tokens, false);
        } catch (ParseCancellationException notSll) {
            tokens.seek(0);
            parser.reset();
            parser.getInterpreter().setPredictionMode(PredictionMode.LL);
            parser.setErrorHandler(new DefaultErrorStrategy());
            parser.addErrorListener(new Reporter(source.name(), diagnostics));
            correctMisspeltModes(tokens, source.name(), diagnostics);
            parsed = numbered(source, parser, tokens, true);
        }
        checkLiterals(source.name(), tokens, diagnostics);
        return parsed;
    }

    /**
     * Reports each string or character literal Java would not read as it shows ({@link Literals}), at
     * the escape at fault: the generated Java holds the literals' values, and must hold exactly what
     * the analysis saw.
     */
    private static void checkLiterals(String file, CommonTokenStream tokens, Diagnostics diagnostics) {
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
            }
        }
    }

    /**
     * {@code synchronus entry main (…)}: a word before {@code entry} that is near a mode is that
     * mode misspelt. It is reported once, at the word, with the mode meant, and read as that mode,
     * so that the block parses and nothing after it reports an echo of the slip.
     */
    private static void correctMisspeltModes(CommonTokenStream tokens, String file, Diagnostics diagnostics) {
        tokens.fill();
        Token word = null;
        for (Token token : tokens.getTokens()) {
            if (token.getChannel() != Token.DEFAULT_CHANNEL) {
                continue;
            }
            if (token.getType() == MASLLexer.ENTRY && word != null && word.getType() == MASLLexer.Identifier) {
                Token misspelt = word;
                Suggestions.closest(misspelt.getText(), MODES.keySet()).ifPresent(mode -> {
                    diagnostics.error(file, misspelt.getLine(), misspelt.getCharPositionInLine() + 1,
                            "unknown mode " + misspelt.getText() + "; did you mean `" + mode + "`?");
                    ((WritableToken) misspelt).setType(MODES.get(mode));
                    ((WritableToken) misspelt).setText(mode);
                });
            }
            word = token;
        }
    }

    /**
     * The program's tree, its nodes numbered as they are built. Only a parse that may have recovered
     * from errors can hold repaired parts: one that did not bail met no syntax error.
     */
    private static Parsed numbered(SourceFile source, MASLParser parser, CommonTokenStream tokens, boolean mayRepair) {
        MaslRuleContext.Numbering numbering = new MaslRuleContext.Numbering();
        ConstantLimits constants = new ConstantLimits();
        parser.removeParseListeners();
        parser.addParseListener(numbering);
        parser.addParseListener(constants);
        MASLParser.ProgramContext tree = parser.program();
        return new Parsed(source, tree, tokens, numbering.count(), mayRepair && hasSyntaxErrors(tree), constants.problems());
    }

    private static boolean hasSyntaxErrors(ParseTree tree) {
        if (tree instanceof ErrorNode) {
            return true;
        }
        if (tree instanceof ParserRuleContext rule && rule.exception != null) {
            return true;
        }
        for (int i = 0; i < tree.getChildCount(); i++) {
            if (hasSyntaxErrors(tree.getChild(i))) {
                return true;
            }
        }
        return false;
    }

    /** Rewords ANTLR's messages: which token was found, and what was expected when that is short. */
    private static final class Reporter extends BaseErrorListener {
        private static final int MAX_LISTED = 4;
        private final String file;
        private final Diagnostics diagnostics;
        private int lastErrorLine;

        Reporter(String file, Diagnostics diagnostics) {
            this.file = file;
            this.diagnostics = diagnostics;
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
            if (found.getType() == MASLLexer.UnterminatedString) {
                diagnostics.error(file, line, column + 1, "unterminated string literal");
                return;
            }
            if (found.getType() == MASLLexer.UNEXPECTED_CHAR) {
                diagnostics.error(file, line, column + 1, "unexpected character " + quoteCharacter(found.getText()));
                return;
            }
            IntervalSet expected = parser.getExpectedTokens();
            if (antlrMessage.startsWith("missing ") && closes(expected)) {
                Token previous = previousToken(parser, found);
                if (previous != null) {
                    diagnostics.error(file, previous.getLine(), endColumn(previous),
                            "expected " + describe(expected, parser.getVocabulary()));
                    return;
                }
            }
            String message = "unexpected " + describe(found);
            boolean listable = expected.size() > 0 && expected.size() <= MAX_LISTED
                    && (error == null || error instanceof InputMismatchException);
            if (listable) {
                message += ", expected " + describe(expected, parser.getVocabulary());
            }
            diagnostics.error(file, line, column + 1, message);
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

        private static String quoteCharacter(String text) {
            char c = text.isEmpty() ? '?' : text.charAt(0);
            return Character.isISOControl(c) ? String.format("U+%04X", (int) c) : "'" + text + "'";
        }
    }
}
