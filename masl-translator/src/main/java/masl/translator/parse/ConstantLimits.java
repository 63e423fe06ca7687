package masl.translator.parse;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import masl.grammar.MASLLexer;
import masl.grammar.MASLParser;
import org.antlr.v4.runtime.ParserRuleContext;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.tree.ErrorNode;
import org.antlr.v4.runtime.tree.ParseTree;
import org.antlr.v4.runtime.tree.ParseTreeListener;
import org.antlr.v4.runtime.tree.TerminalNode;

/**
 * Java's limits on constants, which javac would otherwise meet in the generated code: number literals
 * in range ({@code 2147483648} only after a unary minus), and no string constant over 65,535 bytes
 * (JVMS 4.4.7), a literal or a concatenation javac folds into one constant ({@code "..." + "..."}).
 * A parse listener: the parser completes every node after its children, so the check needs no walk of
 * its own over the tree. It keeps its problems for the analysis, which reports them only for a tree
 * without syntax errors, where javac would meet the constants.
 */
public final class ConstantLimits implements ParseTreeListener {

    /** A constant javac would refuse, at {@code node}, or at {@code token} for a number literal. */
    public record Problem(ParserRuleContext node, Token token, String message) {
    }

    /** The most bytes, in modified UTF-8, that a class file's constant holds. */
    static final int LONGEST_CONSTANT = 65_535;

    /**
     * A constant expression: whether it is a string, and the bytes of its string form (at most, for a
     * number) in a class file ({@code bytes}, modified UTF-8, what the limit counts) and in UTF-8.
     */
    private record Constant(boolean string, long bytes, long utf8) {
    }

    /** Bytes enough for the string form of any number, character or boolean. */
    private static final Constant OTHER = new Constant(false, 25, 25);

    private final Map<ParseTree, Constant> constants = new IdentityHashMap<>();
    private final List<Problem> problems = new ArrayList<>();
    /** Whether some constant string is too long: only then must a node look for one among its children. */
    private boolean tooLongSeen;

    List<Problem> problems() {
        return problems;
    }

    @Override
    public void visitTerminal(TerminalNode terminal) {
        int type = terminal.getSymbol().getType();
        if (type == MASLLexer.IntegerLiteral || type == MASLLexer.FloatingPointLiteral) {
            checkNumber(terminal);
        }
    }

    @Override
    public void exitEveryRule(ParserRuleContext node) {
        Constant constant = node instanceof MASLParser.ExpressionContext || node instanceof MASLParser.PrimaryContext
                || node instanceof MASLParser.LiteralContext ? constant(node) : null;
        if (constant != null) {
            constants.put(node, constant);
            tooLongSeen |= constant.string() && constant.bytes() > LONGEST_CONSTANT;
        }
        if (tooLongSeen && (constant == null || !constant.string())) {
            // The largest constant strings end here: report each child that is one too long.
            for (int i = 0; i < node.getChildCount(); i++) {
                Constant child = constants.get(node.getChild(i));
                if (child != null && child.string() && child.bytes() > LONGEST_CONSTANT) {
                    problems.add(new Problem((ParserRuleContext) node.getChild(i), null, tooLong(child)));
                }
            }
        }
    }

    /** The sizes a user can check: the UTF-8 of the text, and the class file's count where it differs. */
    private static String tooLong(Constant string) {
        String inClassFiles = string.bytes() == string.utf8() ? "" : String.format(", %,d in Java's class files (6 bytes"
                + " for a character beyond U+FFFF, 2 for U+0000)", string.bytes());
        return String.format("a string constant of %,d bytes (in UTF-8)%s: Java holds at most %,d in one; build a longer"
                + " text at run time", string.utf8(), inClassFiles, LONGEST_CONSTANT);
    }

    private void checkNumber(TerminalNode terminal) {
        String text = terminal.getText();
        String problem = switch (terminal.getSymbol().getType()) {
            case MASLLexer.IntegerLiteral -> NumberLiterals.integerProblem(text, isNegated(terminal));
            case MASLLexer.FloatingPointLiteral -> NumberLiterals.floatingProblem(text);
            default -> null;
        };
        if (problem != null) {
            problems.add(new Problem(null, terminal.getSymbol(), problem));
        }
    }

    @Override
    public void enterEveryRule(ParserRuleContext node) {
    }

    @Override
    public void visitErrorNode(ErrorNode node) {
    }

    /** Whether the literal is the operand of a unary minus: {@code -2147483648}. */
    private static boolean isNegated(TerminalNode literal) {
        ParseTree primary = literal.getParent() == null ? null : literal.getParent().getParent();
        return primary instanceof MASLParser.LiteralExprContext
                && primary.getParent() instanceof MASLParser.PrimaryExprContext operand
                && operand.getParent() instanceof MASLParser.PrefixExprContext prefix
                && prefix.op.getType() == MASLLexer.SUB;
    }

    /** The constant {@code node} is, as javac folds it, or null if it is none. */
    private Constant constant(ParseTree node) {
        if (node instanceof MASLParser.LiteralContext literal) {
            return literal(literal);
        }
        if (node instanceof MASLParser.LiteralExprContext literal) {
            return constants.get(literal.literal());
        }
        if (node instanceof MASLParser.ParenExprContext paren) {
            return constants.get(paren.expression());
        }
        if (node instanceof MASLParser.PrimaryExprContext primary) {
            return constants.get(primary.primary());
        }
        if (node instanceof MASLParser.CastExprContext cast) {
            Constant operand = constants.get(cast.expression());
            boolean toString = cast.javaType().getText().equals("String") || cast.javaType().getText().equals("java.lang.String");
            return operand == null ? null : toString ? operand : cast.javaType().primitiveType() != null ? OTHER : null;
        }
        if (node instanceof MASLParser.PrefixExprContext prefix) {
            boolean sign = prefix.op.getType() == MASLLexer.ADD || prefix.op.getType() == MASLLexer.SUB;
            return sign && constants.containsKey(prefix.expression()) ? OTHER : null;
        }
        if (node instanceof MASLParser.NotExprContext not) {
            return constants.containsKey(not.expression()) ? OTHER : null;
        }
        if (node instanceof MASLParser.BinaryExprContext binary) {
            return binary(binary);
        }
        if (node instanceof MASLParser.ConditionalExprContext conditional) {
            Constant whenTrue = constants.get(conditional.whenTrue);
            Constant whenFalse = constants.get(conditional.whenFalse);
            if (!constants.containsKey(conditional.condition) || whenTrue == null || whenFalse == null) {
                return null;
            }
            return new Constant(whenTrue.string() || whenFalse.string(), Math.max(whenTrue.bytes(), whenFalse.bytes()),
                    Math.max(whenTrue.utf8(), whenFalse.utf8()));
        }
        return null;
    }

    private Constant binary(MASLParser.BinaryExprContext binary) {
        Constant left = constants.get(binary.left);
        Constant right = constants.get(binary.right);
        if (left == null || right == null) {
            return null;
        }
        if (binary.op.getType() == MASLLexer.ADD && (left.string() || right.string())) {
            return new Constant(true, left.bytes() + right.bytes(), left.utf8() + right.utf8());
        }
        return OTHER;
    }

    private static Constant literal(MASLParser.LiteralContext literal) {
        if (literal.NULL() != null) {
            return null;
        }
        if (literal.StringLiteral() == null) {
            return OTHER;
        }
        try {
            String text = Literals.string(literal.getText());
            return new Constant(true, modifiedUtf8Length(text), utf8Length(text));
        } catch (Literals.Problem reportedByTheParser) {
            return null;
        }
    }

    /** The bytes of {@code text} in UTF-8; a lone surrogate, which UTF-8 cannot hold, counts the 3 bytes of its replacement. */
    private static long utf8Length(String text) {
        long bytes = 0;
        for (int i = 0; i < text.length(); i += Character.charCount(text.codePointAt(i))) {
            int c = text.codePointAt(i);
            bytes += c <= 0x7f ? 1 : c <= 0x7ff ? 2 : c <= 0xffff ? 3 : 4;
        }
        return bytes;
    }

    /** The bytes of {@code text} in a class file: 1 for U+0001 to U+007F, 2 up to U+07FF and for U+0000, else 3. */
    private static long modifiedUtf8Length(String text) {
        long bytes = 0;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            bytes += c >= 1 && c <= 0x7f ? 1 : c <= 0x7ff ? 2 : 3;
        }
        return bytes;
    }
}
