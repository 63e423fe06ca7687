package masl.translator.parse;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import masl.grammar.MASLLexer;
import masl.translator.diagnostics.Diagnostics;
import masl.translator.diagnostics.Suggestions;
import org.antlr.v4.runtime.CharStream;
import org.antlr.v4.runtime.CommonToken;
import org.antlr.v4.runtime.Token;
import org.antlr.v4.runtime.TokenSource;
import org.antlr.v4.runtime.WritableToken;
import org.antlr.v4.runtime.misc.Pair;

/**
 * Mistakes a reader sees at a glance, found in the tokens of a program that failed to parse, reported
 * once each in the user's terms with the fix, and repaired so that the parser reads on as the user
 * meant and reports nothing more about them: a misspelt keyword ({@code synchronus entry},
 * {@code whle (…) {}, {@code locl int x}), Java habits ({@code String s = "x";} without {@code local},
 * {@code public static int n;}, {@code for (int i = 0; …)}), and a missing or extra {@code }} found
 * by the indentation.
 *
 * <p>A repair is <em>sound</em> when the repaired program is what the user meant: the analysis may
 * then check it, its findings being mistakes of their own. A {@code for} whose variable was
 * declared in it, or a brace placed by the indentation, is a guess: the analysis is not run.
 */
final class TokenRepairs {

    private static final Map<String, Integer> MODES = Map.of("scalar", MASLLexer.SCALAR,
            "synchronous", MASLLexer.SYNCHRONOUS, "asynchronous", MASLLexer.ASYNCHRONOUS);
    private static final Map<String, Integer> SCOPES = Map.of("local", MASLLexer.LOCAL, "shared", MASLLexer.SHARED);
    private static final Map<String, Integer> LABELS = Map.of("LLabel", MASLLexer.LLABEL, "SLabel", MASLLexer.SLABEL);
    private static final Map<String, Integer> HEADED = Map.of("while", MASLLexer.WHILE, "if", MASLLexer.IF,
            "for", MASLLexer.FOR);
    private static final Set<Integer> DECLARING = Set.of(MASLLexer.LOCAL, MASLLexer.SHARED, MASLLexer.LLABEL,
            MASLLexer.SLABEL);
    private static final Set<String> JAVA_MODIFIERS = Set.of("public", "private", "protected", "static");
    private static final Set<Integer> PRIMITIVE_TYPES = Set.of(MASLLexer.BOOLEAN, MASLLexer.BYTE, MASLLexer.CHAR,
            MASLLexer.SHORT, MASLLexer.INT, MASLLexer.LONG, MASLLexer.FLOAT, MASLLexer.DOUBLE);

    private final String file;
    private final Diagnostics diagnostics;
    /** Every token, hidden ones included, in order; repairs insert into it and hide from it. */
    private final List<Token> tokens;
    private boolean sound = true;
    /** Where errors were reported ({@link Position}): the parser reports nothing more there. */
    private final Set<Position> reported = new HashSet<>();

    private TokenRepairs(String file, List<Token> tokens, Diagnostics diagnostics) {
        this.file = file;
        this.tokens = new ArrayList<>(tokens);
        this.diagnostics = diagnostics;
    }

    /** The repaired tokens, whether every repair was sound, and where mistakes were reported. */
    record Repaired(List<Token> tokens, boolean sound, Set<Position> reported) { }

    /** A line and a 1-based column. */
    record Position(int line, int column) { }

    static Repaired repair(String file, List<Token> tokens, Diagnostics diagnostics) {
        TokenRepairs repairs = new TokenRepairs(file, tokens, diagnostics);
        repairs.unexpectedCharacters();
        repairs.statementStarts();
        new Braces(repairs).balance();
        return new Repaired(repairs.tokens, repairs.sound, repairs.reported);
    }

    /** A character outside the language ({@code #}) is reported and dropped: the rest of its line still parses. */
    private void unexpectedCharacters() {
        for (Token token : significant()) {
            if (token.getType() == MASLLexer.UNEXPECTED_CHAR) {
                error(token, "unexpected character " + quoteCharacter(token.getText()));
                hide(token);
            }
        }
    }

    private static String quoteCharacter(String text) {
        char c = text.isEmpty() ? '?' : text.charAt(0);
        return Character.isISOControl(c) ? String.format("U+%04X", (int) c) : "'" + text + "'";
    }

    // ------------------------------------------------------------------ words at the start of a statement

    private void statementStarts() {
        List<Token> significant = significant();
        // For each brace open at this point, whether it opened an entry block, where declarations stand.
        Deque<Boolean> blocks = new ArrayDeque<>();
        for (int i = 0; i < significant.size(); i++) {
            Token token = significant.get(i);
            Token previous = i == 0 ? null : significant.get(i - 1);
            if (token.getType() == MASLLexer.ENTRY && previous != null && previous.getType() == MASLLexer.Identifier) {
                misspeltMode(previous);
            }
            // A word starting a line starts a statement, also when the `;` before it is missing.
            boolean startsStatement = previous == null || previous.getType() == MASLLexer.SEMI
                    || previous.getType() == MASLLexer.LBRACE || previous.getType() == MASLLexer.RBRACE
                    || previous.getLine() < token.getLine();
            if (startsStatement && !blocks.isEmpty()) {
                statementStart(significant, i);
                if (!blocks.peek() && DECLARING.contains(token.getType()) && token.getChannel() == Token.DEFAULT_CHANNEL) {
                    declarationOutsideEntryBlock(significant, i);
                }
            } else if (startsStatement && JAVA_MODIFIERS.contains(token.getText())
                    || token.getText().equals("class") && token.getType() == MASLLexer.Identifier && blocks.isEmpty()) {
                javaOutsideBlocks(significant, i);
            }
            if (token.getChannel() == Token.DEFAULT_CHANNEL && token.getType() == MASLLexer.LBRACE) {
                blocks.push(opensEntryBlock(significant, i));
            } else if (token.getChannel() == Token.DEFAULT_CHANNEL && token.getType() == MASLLexer.RBRACE
                    && !blocks.isEmpty()) {
                blocks.pop();
            }
            if (token.getType() == MASLLexer.FOR && i + 1 < significant.size()
                    && significant.get(i + 1).getType() == MASLLexer.LPAREN) {
                declarationInFor(significant, i + 2);
            }
        }
    }

    /** Whether the {@code {} at {@code brace} opens an entry block: {@code MODE entry NAME (TEST) {}. */
    private static boolean opensEntryBlock(List<Token> significant, int brace) {
        if (brace == 0 || significant.get(brace - 1).getType() != MASLLexer.RPAREN) {
            return false;
        }
        int depth = 0;
        for (int i = brace - 1; i >= 0; i--) {
            int type = significant.get(i).getType();
            depth += type == MASLLexer.RPAREN ? 1 : type == MASLLexer.LPAREN ? -1 : 0;
            if (depth == 0) {
                return i >= 2 && significant.get(i - 2).getType() == MASLLexer.ENTRY;
            }
        }
        return false;
    }

    /**
     * {@code if (c) { local int t = 0; … }}: only an entry block declares (§3); the declaration is
     * reported once and dropped, so that the rest parses.
     */
    private void declarationOutsideEntryBlock(List<Token> significant, int start) {
        error(significant.get(start), "only an entry block declares, at its head: move this declaration to the"
                + " head of the entry block around it");
        for (int i = start; i < significant.size(); i++) {
            Token token = significant.get(i);
            if (token.getType() == MASLLexer.RBRACE) {
                break;
            }
            hide(token);
            if (token.getType() == MASLLexer.SEMI) {
                break;
            }
        }
        sound = false;
    }

    /**
     * {@code synchronus entry main (…)}: a word before {@code entry} that is near a mode is that mode
     * misspelt.
     */
    private void misspeltMode(Token word) {
        Suggestions.closest(word.getText(), MODES.keySet()).ifPresent(mode -> {
            error(word, "unknown mode " + word.getText() + "; did you mean `" + mode + "`?");
            retype(word, MODES.get(mode), mode);
        });
    }

    private void statementStart(List<Token> significant, int start) {
        Token word = significant.get(start);
        int after = start + 1;
        if (word.getType() != MASLLexer.Identifier || after >= significant.size()) {
            return;
        }
        Token next = significant.get(after);
        if (JAVA_MODIFIERS.contains(word.getText())) {
            javaModifiers(significant, start);
            return;
        }
        boolean declares = declarationAt(significant, start);
        boolean namesAType = PRIMITIVE_TYPES.contains(next.getType()) || next.getType() == MASLLexer.FINAL
                || next.getType() == MASLLexer.EVENT || declarationAt(significant, after);
        if (namesAType && misspelt(word, SCOPES)) {
            return;
        }
        if (declares && typeEnd(significant, start) == after && misspelt(word, LABELS)) {
            return;
        }
        if (next.getType() == MASLLexer.LPAREN && isHeaderFollowedByStatement(significant, after)
                && misspelt(word, HEADED)) {
            return;
        }
        if (declares) {
            undeclaredScope(significant, start, typeEnd(significant, start));
        }
    }

    /** Whether a type, a name and {@code =}, {@code ;} or {@code ,} start at {@code start}: a declaration. */
    private static boolean declarationAt(List<Token> significant, int start) {
        int typeEnd = typeEnd(significant, start);
        return typeEnd > start && typeEnd + 1 < significant.size()
                && significant.get(typeEnd).getType() == MASLLexer.Identifier
                && Set.of(MASLLexer.ASSIGN, MASLLexer.SEMI, MASLLexer.COMMA)
                        .contains(significant.get(typeEnd + 1).getType());
    }

    /**
     * {@code public class Mission { … }}: Java's classes and modifiers have no place around MASL's
     * blocks. A class wrapped around the program is reported once and read as if it were not there.
     */
    private void javaOutsideBlocks(List<Token> significant, int start) {
        Token word = significant.get(start);
        if (word.getChannel() != Token.DEFAULT_CHANNEL) {
            return;
        }
        error(word, "`" + word.getText() + "` is Java, not MASL: a program is its imports, its agents and one entry"
                + " block (`scalar entry main (true) { … }`), with no classes or methods");
        int i = start;
        while (i < significant.size() && JAVA_MODIFIERS.contains(significant.get(i).getText())) {
            i++;
        }
        boolean wrapsTheProgram = i + 2 < significant.size() && significant.get(i).getText().equals("class")
                && significant.get(i + 1).getType() == MASLLexer.Identifier
                && significant.get(i + 2).getType() == MASLLexer.LBRACE;
        int close = wrapsTheProgram ? matchingBrace(significant, i + 2) : -1;
        if (close < 0) {
            // A method's header is dropped too: its body parses as a block, its parameters undeclared.
            int parameters = typeEnd(significant, i) + 1;
            boolean method = parameters < significant.size() && parameters > i + 1
                    && significant.get(parameters - 1).getType() == MASLLexer.Identifier
                    && significant.get(parameters).getType() == MASLLexer.LPAREN;
            int end = method ? matching(significant, parameters) : -1;
            for (int hidden = start; hidden < (end < 0 ? i : end + 1); hidden++) {
                hide(significant.get(hidden));
            }
            sound = false;
            return;
        }
        for (int hidden = start; hidden <= i + 2; hidden++) {
            hide(significant.get(hidden));
        }
        hide(significant.get(close));
    }

    /** The index of the {@code }} closing the {@code {} at {@code open}, or -1. */
    private static int matchingBrace(List<Token> significant, int open) {
        int depth = 0;
        for (int i = open; i < significant.size(); i++) {
            int type = significant.get(i).getType();
            depth += type == MASLLexer.LBRACE ? 1 : type == MASLLexer.RBRACE ? -1 : 0;
            if (depth == 0) {
                return i;
            }
        }
        return -1;
    }

    /** Reports {@code word} as the keyword near it among {@code keywords} and reads it so; false if none is near. */
    private boolean misspelt(Token word, Map<String, Integer> keywords) {
        return Suggestions.closest(word.getText(), keywords.keySet()).map(keyword -> {
            error(word, "unknown keyword " + word.getText() + "; did you mean `" + keyword + "`?");
            retype(word, keywords.get(keyword), keyword);
            return true;
        }).orElse(false);
    }

    /** {@code whle (x < 3) {}: a parenthesised header followed by a block or a statement, not by an operator or {@code ;}. */
    private static boolean isHeaderFollowedByStatement(List<Token> significant, int open) {
        int close = matching(significant, open);
        if (close < 0 || close + 1 >= significant.size()) {
            return false;
        }
        int type = significant.get(close + 1).getType();
        return type == MASLLexer.LBRACE || type == MASLLexer.Identifier || type == MASLLexer.IF
                || type == MASLLexer.WHILE || type == MASLLexer.FOR || type == MASLLexer.BREAK;
    }

    /** {@code String s = "x";}: a Java declaration, read as {@code local String s = "x";}. */
    private void undeclaredScope(List<Token> significant, int start, int nameIndex) {
        Token first = significant.get(start);
        error(first, "a declaration needs `local` or `shared` and goes at the head of its block: `local "
                + textOf(significant, start, nameIndex) + " …;`");
        insertBefore(first, MASLLexer.LOCAL, "local");
    }

    /** {@code public static int n = 0;}: Java's modifiers, read as {@code local}. */
    private void javaModifiers(List<Token> significant, int start) {
        int end = start;
        while (end < significant.size() && JAVA_MODIFIERS.contains(significant.get(end).getText())) {
            end++;
        }
        int typeEnd = typeEnd(significant, end);
        if (!declarationAt(significant, end)) {
            javaOutsideBlocks(significant, start);
            return;
        }
        Token first = significant.get(start);
        error(first, "`" + textOf(significant, start, end - 1) + "` is Java, not MASL: a variable is `local` (each"
                + " agent's own) or `shared` (one for the block's members), declared at the head of its block: `local "
                + textOf(significant, end, typeEnd) + " …;`");
        insertBefore(first, MASLLexer.LOCAL, "local");
        for (int i = start; i < end; i++) {
            hide(significant.get(i));
        }
    }

    /** {@code for (int i = 0; …)}: MASL declares at the head of a block; the type is dropped so the rest parses. */
    private void declarationInFor(List<Token> significant, int start) {
        if (start >= significant.size()) {
            return;
        }
        int typeEnd = typeEnd(significant, start);
        if (typeEnd == start || typeEnd + 1 >= significant.size()
                || significant.get(typeEnd).getType() != MASLLexer.Identifier
                || significant.get(typeEnd + 1).getType() != MASLLexer.ASSIGN) {
            return;
        }
        String name = significant.get(typeEnd).getText();
        error(significant.get(start), "a for cannot declare its variable: declare `local "
                + textOf(significant, start, typeEnd) + ";` at the head of the block, then write `for (" + name
                + " = …; …)`");
        for (int i = start; i < typeEnd; i++) {
            hide(significant.get(i));
        }
        sound = false;
    }

    /**
     * The index after the Java type that starts at {@code start} ({@code int}, {@code String},
     * {@code java.util.Vector<Integer>}, {@code double[]}), or {@code start} if none starts there.
     */
    private static int typeEnd(List<Token> significant, int start) {
        int i = start;
        if (i >= significant.size()) {
            return start;
        }
        if (PRIMITIVE_TYPES.contains(significant.get(i).getType())) {
            i++;
        } else if (significant.get(i).getType() == MASLLexer.Identifier) {
            i++;
            while (i + 1 < significant.size() && significant.get(i).getType() == MASLLexer.DOT
                    && significant.get(i + 1).getType() == MASLLexer.Identifier) {
                i += 2;
            }
            if (i < significant.size() && significant.get(i).getType() == MASLLexer.LT) {
                int depth = 0;
                do {
                    int type = significant.get(i).getType();
                    depth += type == MASLLexer.LT ? 1 : type == MASLLexer.GT ? -1 : 0;
                    boolean inType = type == MASLLexer.LT || type == MASLLexer.GT || type == MASLLexer.COMMA
                            || type == MASLLexer.DOT || type == MASLLexer.Identifier || type == MASLLexer.QUESTION
                            || type == MASLLexer.LBRACK || type == MASLLexer.RBRACK
                            || PRIMITIVE_TYPES.contains(type);
                    if (!inType) {
                        return start;
                    }
                    i++;
                } while (depth > 0 && i < significant.size());
            }
        } else {
            return start;
        }
        while (i + 1 < significant.size() && significant.get(i).getType() == MASLLexer.LBRACK
                && significant.get(i + 1).getType() == MASLLexer.RBRACK) {
            i += 2;
        }
        return i;
    }

    /** The index of the {@code )} closing the {@code (} at {@code open}, or -1. */
    private static int matching(List<Token> significant, int open) {
        int depth = 0;
        for (int i = open; i < significant.size(); i++) {
            int type = significant.get(i).getType();
            if (type == MASLLexer.LPAREN) {
                depth++;
            } else if (type == MASLLexer.RPAREN && --depth == 0) {
                return i;
            } else if (type == MASLLexer.SEMI || type == MASLLexer.LBRACE || type == MASLLexer.RBRACE) {
                return -1;
            }
        }
        return -1;
    }

    private static String textOf(List<Token> significant, int from, int to) {
        StringBuilder text = new StringBuilder();
        for (int i = from; i <= to; i++) {
            Token token = significant.get(i);
            boolean glued = i == from || token.getType() == MASLLexer.DOT || token.getType() == MASLLexer.LT
                    || token.getType() == MASLLexer.GT || token.getType() == MASLLexer.LBRACK
                    || token.getType() == MASLLexer.RBRACK || significant.get(i - 1).getType() == MASLLexer.DOT
                    || significant.get(i - 1).getType() == MASLLexer.LT;
            text.append(glued ? "" : " ").append(token.getText());
        }
        return text.toString();
    }

    // ------------------------------------------------------------------ editing the tokens

    List<Token> significant() {
        List<Token> significant = new ArrayList<>();
        for (Token token : tokens) {
            if (token.getChannel() == Token.DEFAULT_CHANNEL && token.getType() != Token.EOF) {
                significant.add(token);
            }
        }
        return significant;
    }

    void error(Token at, String message) {
        error(at.getLine(), at.getCharPositionInLine() + 1, message);
    }

    void error(int line, int column, String message) {
        reported.add(new Position(line, column));
        diagnostics.error(file, line, column, message);
    }

    void unsound() {
        sound = false;
    }

    private static void retype(Token token, int type, String text) {
        ((WritableToken) token).setType(type);
        ((WritableToken) token).setText(text);
    }

    /** Takes {@code token} out of the parser's sight, as a comment is. */
    static void hide(Token token) {
        ((WritableToken) token).setChannel(Token.HIDDEN_CHANNEL);
    }

    /** Inserts a token the user left out right before {@code next}, at its position. */
    void insertBefore(Token next, int type, String text) {
        tokens.add(tokens.indexOf(next), inserted(next, type, text, next.getCharPositionInLine(), next.getStartIndex()));
    }

    /** Inserts a token the user left out right after {@code previous}, where it ends. */
    void insertAfter(Token previous, int type, String text) {
        tokens.add(tokens.indexOf(previous) + 1, inserted(previous, type, text,
                previous.getCharPositionInLine() + previous.getText().length(), previous.getStopIndex() + 1));
    }

    /** A token at {@code index} of the text, on the line of {@code neighbour}, from the same source (ANTLR's recovery reads it). */
    private static Token inserted(Token neighbour, int type, String text, int column, int index) {
        CommonToken token = new InsertedToken(new Pair<>(neighbour.getTokenSource(), neighbour.getInputStream()), type,
                index);
        token.setText(text);
        token.setLine(neighbour.getLine());
        token.setCharPositionInLine(column);
        return token;
    }

    /** Whether a repair put {@code token} in, the user having left it out. */
    static boolean wasLeftOut(Token token) {
        return token instanceof InsertedToken;
    }

    /** A token the user left out, which a repair put in. */
    private static final class InsertedToken extends CommonToken {
        private static final long serialVersionUID = 1L;

        InsertedToken(Pair<TokenSource, CharStream> source, int type, int index) {
            super(source, type, Token.DEFAULT_CHANNEL, index, index - 1);
        }
    }
}
