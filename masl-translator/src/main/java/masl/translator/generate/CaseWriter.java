package masl.translator.generate;

import java.util.ArrayList;
import java.util.List;

/**
 * Writes the cases of a generated state machine, one per resumption point ({@link StateMachineWriter}
 * puts them in {@code resume}). Code refers to resumption points through {@link Point}s, created
 * before their place is known (a jump forward) and placed later; cases are numbered in the order they
 * are placed, so the numbers follow the program. Several points placed with no code between them
 * share one case.
 */
final class CaseWriter {

    /**
     * How many characters of Java a case may hold before the next statement starts a case of its own,
     * so that a long run of statements with no resumption point in between (thousands of declarations)
     * can still be split between methods (a Java method holds at most 64 KB of bytecode).
     */
    static final int LONGEST_CASE = 4_000;

    /**
     * The most characters of Java one statement may make: a case cannot be split inside a statement,
     * and Java's bytecode takes at most one byte a character (about a third, mostly), so this much
     * fits the 64 KB of a method with room for the machine around it.
     */
    static final int LARGEST_STATEMENT = 60_000;

    /** A resumption point: a case of the switch once placed. */
    static final class Point {
        private Case target;

        /** The case number, once the cases are rendered. */
        int number() {
            if (target == null) {
                throw new IllegalStateException("a resumption point was used but never placed");
            }
            return target.number;
        }
    }

    /** A case of the switch: its number, its comment and its lines, once rendered. */
    static final class Case {
        private int number;
        private String comment;
        /** The MASL statement written last in the case: the one whose runtime call ends it. */
        private String lastStatement;
        private final List<Object> lines = new ArrayList<>();
        /** Whether the case ends with a jump or a return: else it falls through into the next one. */
        private boolean endsInJump;
        /** The characters of its lines: a measure of its bytecode. */
        private int size;

        private Case(String comment) {
            this.comment = comment;
            this.lastStatement = comment;
        }

        int number() {
            return number;
        }

        /** The MASL line of the case, or null. */
        String comment() {
            return comment;
        }

        /** The MASL statement whose runtime call ends the case, if it is not the one of the comment; else null. */
        String callSource() {
            return lastStatement != null && !lastStatement.equals(comment) ? lastStatement : null;
        }

        boolean fallsThrough() {
            return !endsInJump;
        }

        int size() {
            return size;
        }
    }

    /**
     * A line that sets {@code pc} to a resumption point, resolved when the cases are numbered:
     * {@code before}, the assignment, {@code after}.
     */
    private record Jump(String indent, String before, Point point, String after) {
    }

    /** A line that returns from the state machine: the agent suspended or finished. */
    private record Return(String indent, String before, String after) {
    }

    private static final String[] INDENTS = {"", "    ", "        ", "            ", "                "};

    private final List<Case> cases = new ArrayList<>();
    private Case current;
    /** The point the current case last set {@code pc} to outside any Java block, or null. */
    private Point pcSetTo;
    private boolean terminated = true;
    private boolean grewTooLarge;
    private int indent;

    Point point() {
        return new Point();
    }

    /**
     * Makes {@code point} the code that follows. Starts a new case, unless the current one has no
     * code yet, in which case the point shares it. Code that falls into the new case sets {@code pc}
     * to it first: an agent failing there is reported at this case's statement, not the one before.
     */
    void place(Point point, String comment) {
        if (indent > 0) {
            throw new IllegalStateException("a resumption point cannot stand inside a Java block");
        }
        if (current == null || !current.lines.isEmpty() || terminated) {
            if (current != null && !terminated && pcSetTo != point) {
                setPc(point);
            }
            current = newCase(comment);
        } else if (current.comment == null) {
            current.comment = comment;
        }
        if (comment != null) {
            current.lastStatement = comment;
        }
        point.target = current;
        terminated = false;
    }

    /** Whether the code written last jumped away or returned: what follows it is never reached. */
    boolean isTerminated() {
        return terminated;
    }

    /**
     * Where a MASL statement starts: outside any Java block, after code of another statement, it
     * starts a case of its own, which that code falls into, so that {@code pc} names the statement
     * while it runs (an agent that fails in it is reported at its line).
     */
    void statementOwnCase() {
        if (indent == 0 && !terminated && current != null && !current.lines.isEmpty()) {
            place(point(), null);
        }
    }

    /**
     * Where a statement starts, outside any Java block: if the current case has grown past
     * {@value #LONGEST_CASE} characters, the statement starts a case of its own, which the previous
     * code falls into. Such a case is no resumption point, only a place to split the machine.
     */
    void statementStart() {
        if (indent == 0 && !terminated && current != null && current.size > LONGEST_CASE) {
            String continued = current.lastStatement;
            place(point(), null);
            current.lastStatement = continued;
        }
    }

    /**
     * Whether a case grew past {@value #LARGEST_STATEMENT} characters since this was last asked: the
     * statement just written is too large for a Java method.
     */
    boolean tooLarge() {
        boolean grown = grewTooLarge;
        grewTooLarge = false;
        return grown;
    }

    /** A line of code in the current case, starting an (unreachable) case if the previous code jumped away. */
    void line(String code) {
        add(indentation() + code);
    }

    /**
     * A line holding the {@code return} that leaves the state machine, between {@code before} and
     * {@code after}: {@code return;} in {@code resume}, {@code return false;} in a part of it.
     */
    void returning(String before, String after) {
        add(new Return(indentation(), before, after));
    }

    /** {@code if (!call) return;}: the agent suspends unless {@code call} lets it go on. */
    void returnUnless(String call) {
        returning("if (!" + call + ") ", "");
    }

    /** A {@code return;} that ends the case: the agent finished. */
    void endWithReturn() {
        returning("", "");
        terminate();
    }

    /** Names the code that follows: the comment of the current case if it has none and no code yet, else a line. */
    void note(String text) {
        if (!terminated && current != null && current.lines.isEmpty() && current.comment == null) {
            current.comment = text;
        } else {
            comment(text);
        }
        current.lastStatement = text;
    }

    /** {@code } else {}: closes a Java block and opens the next one. */
    void reopen(String code) {
        indent--;
        line(code);
        indent++;
    }

    /** A comment line in the current case. */
    void comment(String text) {
        line("// " + JavaText.comment(text));
    }

    void open(String code) {
        line(code);
        indent++;
    }

    void close(String code) {
        indent--;
        line(code);
    }

    /** {@code pc = point;} */
    void setPc(Point point) {
        add(new Jump(indentation(), "", point, ""));
        if (indent == 0) {
            pcSetTo = point;
        }
    }

    /** {@code pc = point; continue;}: the rest of the case is never reached. */
    void jump(Point point) {
        setPc(point);
        line("continue;");
        if (indent == 0) {
            terminate();
        }
    }

    /** A line that ends the case ({@code continue;}). */
    void end(String code) {
        line(code);
        terminate();
    }

    /** The text of a jump to {@code point} inside a line: {@code prefix + "pc = N; continue;" + suffix}. */
    void jumpLine(String prefix, Point point, String suffix) {
        add(new Jump(indentation() + prefix, "", point, " continue;" + suffix));
    }

    /**
     * A runtime call that may suspend: {@code pc = next; if (!call) return;} then {@code next} is
     * placed right after, where the call's "go on" falls through.
     */
    void suspending(String call, Point next) {
        setPc(next);
        returnUnless(call);
        place(next, null);
    }

    private String indentation() {
        return indent < INDENTS.length ? INDENTS[indent] : "    ".repeat(indent);
    }

    private void add(Object line) {
        if (terminated || current == null) {
            current = newCase(null);
            terminated = false;
        }
        current.lines.add(line);
        int before = current.size;
        current.size += size(line) + 1;
        grewTooLarge |= before <= LARGEST_STATEMENT && current.size > LARGEST_STATEMENT;
    }

    private void terminate() {
        terminated = true;
        current.endsInJump = true;
    }

    private Case newCase(String comment) {
        pcSetTo = null;
        Case created = new Case(comment);
        cases.add(created);
        return created;
    }

    /** Numbers the cases, in the order they were placed: call once all the code is written. */
    void number() {
        for (int i = 0; i < cases.size(); i++) {
            cases.get(i).number = i;
        }
    }

    /** The cases in order. Call after {@link #number}. */
    List<Case> cases() {
        return cases;
    }

    /**
     * Appends {@code c} to {@code text}, each line indented by {@code margin}. In a part of a split
     * state machine a return is {@code return false;}, and {@code pc} is set through the program's
     * {@code setPc} ({@link StateMachineWriter}).
     */
    static void render(StringBuilder text, Case c, String margin, boolean inPart) {
        text.append(margin).append("case ").append(c.number).append(':');
        if (c.comment != null) {
            text.append(" // ").append(JavaText.comment(c.comment));
        }
        text.append('\n');
        for (Object line : c.lines) {
            text.append(margin).append("    ");
            if (line instanceof Jump jump) {
                text.append(jump.indent()).append(jump.before()).append(inPart ? "setPc(" : "pc = ")
                        .append(jump.point().number()).append(inPart ? ");" : ";").append(jump.after());
            } else if (line instanceof Return exit) {
                text.append(exit.indent()).append(exit.before()).append(inPart ? "return false;" : "return;")
                        .append(exit.after());
            } else {
                text.append((String) line);
            }
            text.append('\n');
        }
    }

    /**
     * The characters of a line that become bytecode, about: a string or character literal counts as
     * the 3 bytes that load its constant, a comment as nothing; a jump's number and a return's words
     * are not known yet.
     */
    private static int size(Object line) {
        if (line instanceof Jump jump) {
            return jump.indent().length() + size(jump.before()) + size(jump.after()) + "pc = ;".length() + 5;
        }
        if (line instanceof Return exit) {
            return exit.indent().length() + size(exit.before()) + size(exit.after()) + 13;
        }
        return size((String) line);
    }

    private static int size(String code) {
        int size = 0;
        int i = 0;
        while (i < code.length()) {
            char c = code.charAt(i);
            if (c == '/' && i + 1 < code.length() && code.charAt(i + 1) == '/') {
                break;
            }
            if (c == '"' || c == '\'') {
                i = endOfLiteral(code, i);
                size += 3;
            } else {
                i++;
                size++;
            }
        }
        return size;
    }

    /** The index after the literal that starts at {@code start} with its quote. */
    private static int endOfLiteral(String code, int start) {
        char quote = code.charAt(start);
        int i = start + 1;
        while (i < code.length() && code.charAt(i) != quote) {
            i += code.charAt(i) == '\\' ? 2 : 1;
        }
        return i + 1;
    }
}
