package masl.translator.generate;

import java.util.ArrayList;
import java.util.List;

/**
 * Writes the body of a generated {@code resume} method: a {@code switch (pc)} of cases, one per
 * resumption point. Code refers to resumption points through {@link Point}s, created before their
 * place is known (a jump forward) and placed later; cases are numbered in the order they are placed,
 * so the numbers follow the program. Several points placed with no code between them share one case.
 */
final class CaseWriter {

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

    private static final class Case {
        int number;
        String comment;
        /** The MASL statement written last in the case: the one whose runtime call ends it. */
        String lastStatement;
        final List<Object> lines = new ArrayList<>();

        Case(String comment) {
            this.comment = comment;
            this.lastStatement = comment;
        }
    }

    /** A line whose text names a resumption point, resolved when the cases are numbered. */
    private record Jump(String indent, String before, Point point, String after) {
    }

    private static final String[] INDENTS = {"", "    ", "        ", "            ", "                "};

    private final List<Case> cases = new ArrayList<>();
    private Case current;
    private boolean terminated = true;
    private int indent;

    Point point() {
        return new Point();
    }

    /**
     * Makes {@code point} the code that follows. Starts a new case, unless the current one has no
     * code yet, in which case the point shares it.
     */
    void place(Point point, String comment) {
        if (indent > 0) {
            throw new IllegalStateException("a resumption point cannot stand inside a Java block");
        }
        if (current == null || !current.lines.isEmpty() || terminated) {
            current = new Case(comment);
            cases.add(current);
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

    /** A line of code in the current case, starting an (unreachable) case if the previous code jumped away. */
    void line(String code) {
        startIfTerminated();
        current.lines.add(indentation() + code);
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
        startIfTerminated();
        current.lines.add(new Jump(indentation(), "pc = ", point, ";"));
    }

    /** {@code pc = point; continue;}: the rest of the case is never reached. */
    void jump(Point point) {
        setPc(point);
        line("continue;");
        if (indent == 0) {
            terminated = true;
        }
    }

    /** A line that ends the case ({@code return;}). */
    void end(String code) {
        line(code);
        terminated = true;
    }

    /** The text of a jump to {@code point} inside a line: {@code prefix + "pc = N; continue;" + suffix}. */
    void jumpLine(String prefix, Point point, String suffix) {
        startIfTerminated();
        current.lines.add(new Jump(indentation() + prefix, "pc = ", point, "; continue;" + suffix));
    }

    /**
     * A runtime call that may suspend: {@code pc = next; if (!call) return;} then {@code next} is
     * placed right after, where the call's "go on" falls through.
     */
    void suspending(String call, Point next) {
        setPc(next);
        line("if (!" + call + ") return;");
        place(next, null);
    }

    private String indentation() {
        return indent < INDENTS.length ? INDENTS[indent] : "    ".repeat(indent);
    }

    private void startIfTerminated() {
        if (terminated || current == null) {
            current = new Case(null);
            cases.add(current);
            terminated = false;
        }
    }

    /**
     * The {@code sourceAt} method of the program: each commented case's number and its comment (the
     * MASL line), for the runtime's reports. Call after {@link #number}.
     */
    void sourceAtMethod(JavaLines out) {
        out.add("    @Override");
        out.add("    protected String sourceAt(int pc) {");
        out.add("        return switch (pc) {");
        StringBuilder text = out.buffer();
        for (Case c : cases) {
            if (c.comment != null) {
                JavaText.quote(text.append("            case ").append(c.number).append(" -> "), c.comment).append(";\n");
            }
        }
        out.add("            default -> null;");
        out.add("        };");
        out.add("    }");
    }

    /**
     * The {@code sourceOfCallIn} method: for each case holding several statements, the last one (the
     * statement whose runtime call ends the case, say {@code .logln(x);} in a case that begins with
     * {@code else}); other cases fall back on {@code sourceAt}. Call after {@link #number}.
     */
    void sourceOfCallInMethod(JavaLines out) {
        out.add("    @Override");
        out.add("    protected String sourceOfCallIn(int pc) {");
        out.add("        return switch (pc) {");
        StringBuilder text = out.buffer();
        for (Case c : cases) {
            if (c.lastStatement != null && !c.lastStatement.equals(c.comment)) {
                JavaText.quote(text.append("            case ").append(c.number).append(" -> "), c.lastStatement)
                        .append(";\n");
            }
        }
        out.add("            default -> sourceAt(pc);");
        out.add("        };");
        out.add("    }");
    }

    /** Numbers the cases, in the order they were placed: call once all the code is written. */
    void number() {
        for (int i = 0; i < cases.size(); i++) {
            cases.get(i).number = i;
        }
    }

    /** Adds the cases to {@code out}, each line indented by {@code margin}. Call after {@link #number}. */
    void render(JavaLines out, String margin) {
        StringBuilder text = out.buffer();
        for (Case c : cases) {
            text.append(margin).append("case ").append(c.number).append(':');
            if (c.comment != null) {
                text.append(" // ").append(JavaText.comment(c.comment));
            }
            text.append('\n');
            for (Object line : c.lines) {
                text.append(margin).append("    ");
                if (line instanceof Jump jump) {
                    text.append(jump.indent()).append(jump.before()).append(jump.point().number()).append(jump.after());
                } else {
                    text.append((String) line);
                }
                text.append('\n');
            }
        }
    }
}
