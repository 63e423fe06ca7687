package masl.translator.generate;

import java.util.ArrayList;
import java.util.List;

/**
 * Writes the methods of a program class that hold its state machine (generated-code contract §1.2):
 * {@code resume}, a {@code switch (pc)} over the cases of a {@link CaseWriter}, and {@code sourceAt}
 * and {@code sourceOfCallIn}, which name the MASL statement of a case for the runtime's reports.
 *
 * <p>A Java method holds at most 64 KB of bytecode, and a class 65,535 constants. A machine larger
 * than {@value #LARGEST_PART} characters of Java is split into parts by ranges of {@code pc}, each
 * an inner class of its own ({@code From195} holds the cases from 195): {@code resume} calls the
 * part that holds {@code pc}; a part returns false once the agent suspended or finished, true to go
 * on at a {@code pc} another part holds. A small machine is one {@code resume}.
 */
final class StateMachineWriter {

    /**
     * The characters of Java in one part: about a quarter of them become bytecode, so a part stays far
     * below the 64 KB limit, and below the 8,000 bytes above which HotSpot does not compile a method.
     */
    static final int LARGEST_PART = 16_000;

    /** A range of consecutive cases written as one method. */
    private record Part(List<CaseWriter.Case> cases) {
        int first() {
            return cases.get(0).number();
        }

        int end() {
            return cases.get(cases.size() - 1).number() + 1;
        }
    }

    private static final String CASE_MARGIN = "                ";
    private static final String PART_CASE_MARGIN = "                    ";

    private final List<Part> parts;

    /** @param cases numbered ({@link CaseWriter#number}) */
    StateMachineWriter(CaseWriter cases) {
        this.parts = split(cases.cases());
    }

    private static List<Part> split(List<CaseWriter.Case> cases) {
        List<Part> parts = new ArrayList<>();
        List<CaseWriter.Case> part = new ArrayList<>();
        int size = 0;
        for (CaseWriter.Case c : cases) {
            if (size + c.size() > LARGEST_PART && !part.isEmpty()) {
                parts.add(new Part(part));
                part = new ArrayList<>();
                size = 0;
            }
            part.add(c);
            size += c.size();
        }
        if (!part.isEmpty()) {
            parts.add(new Part(part));
        }
        return parts;
    }

    /** Adds {@code resume}, {@code sourceAt} and {@code sourceOfCallIn} (and their parts), with a blank line between methods. */
    void write(JavaLines out) {
        if (parts.size() <= 1) {
            writeWhole(out);
        } else {
            writeParts(out);
        }
    }

    private void writeWhole(JavaLines out) {
        List<CaseWriter.Case> cases = parts.isEmpty() ? List.of() : parts.get(0).cases();
        out.add("    @Override");
        out.add("    @SuppressWarnings(\"fallthrough\") // resumption points fall through into the next one");
        out.add("    protected void resume(AgentContext ctx) {");
        out.add("        while (true) {");
        out.add("            switch (pc) {");
        for (CaseWriter.Case c : cases) {
            CaseWriter.render(out.buffer(), c, CASE_MARGIN, false);
        }
        out.add("                default:");
        out.add("                    throw new IllegalStateException(\"pc \" + pc);");
        out.add("            }");
        out.add("        }");
        out.add("    }");
        out.add("");
        out.add("    @Override");
        out.add("    protected String sourceAt(int pc) {");
        sourceSwitch(out, "        ", cases, false, "null");
        out.add("    }");
        out.add("");
        out.add("    @Override");
        out.add("    protected String sourceOfCallIn(int pc) {");
        sourceSwitch(out, "        ", cases, true, "sourceAt(pc)");
        out.add("    }");
    }

    private void writeParts(JavaLines out) {
        out.add("    /*");
        out.add("     * The state machine in " + parts.size() + " parts by ranges of pc, each a class of its own: a Java method");
        out.add("     * holds at most 64 KB of bytecode, a class 65,535 constants. A part returns false once the agent");
        out.add("     * suspended or finished, true to go on at a pc that another part holds.");
        out.add("     */");
        for (Part part : parts) {
            out.add("    private final From" + part.first() + " from" + part.first() + " = new From" + part.first() + "();");
        }
        out.add("");
        out.add("    @Override");
        out.add("    protected void resume(AgentContext ctx) {");
        out.add("        boolean goOn;");
        out.add("        do {");
        String keyword = "if";
        for (Part part : parts) {
            out.add("            " + keyword + " (pc < " + part.end() + ") {");
            out.add("                goOn = from" + part.first() + ".resume(ctx);");
            keyword = "} else if";
        }
        out.add("            } else {");
        out.add("                throw new IllegalStateException(\"pc \" + pc);");
        out.add("            }");
        out.add("        } while (goOn);");
        out.add("    }");
        out.add("");
        dispatch(out, "String sourceAt(int pc)", "sourceAt", "null");
        out.add("");
        dispatch(out, "String sourceOfCallIn(int pc)", "sourceOfCallIn", "sourceAt(pc)");
        out.add("");
        out.add("    /**");
        out.add("     * How the parts set pc: javac gives an inner class each access of a field inherited from another");
        out.add("     * package a synthetic method of its own in this class, and a class holds 65,535 constants.");
        out.add("     */");
        out.add("    private void setPc(int next) {");
        out.add("        pc = next;");
        out.add("    }");
        for (int i = 0; i < parts.size(); i++) {
            out.add("");
            writePart(out, parts.get(i), i + 1 < parts.size());
        }
    }

    private static void writePart(JavaLines out, Part part, boolean followed) {
        List<CaseWriter.Case> cases = part.cases();
        CaseWriter.Case last = cases.get(cases.size() - 1);
        out.add("    /** Resumption points " + part.first() + " to " + (part.end() - 1) + ". */");
        out.add("    private final class From" + part.first() + " {");
        out.add("");
        out.add("        @SuppressWarnings(\"fallthrough\") // resumption points fall through into the next one");
        out.add("        boolean resume(AgentContext ctx) {");
        out.add("            while (true) {");
        out.add("                switch (pc()) {");
        for (CaseWriter.Case c : cases) {
            CaseWriter.render(out.buffer(), c, PART_CASE_MARGIN, true);
        }
        if (followed && last.fallsThrough()) {
            out.add(PART_CASE_MARGIN + "    setPc(" + part.end() + "); // on in the next part");
            out.add(PART_CASE_MARGIN + "    return true;");
        }
        out.add("                    default:");
        out.add("                        return true;");
        out.add("                }");
        out.add("            }");
        out.add("        }");
        out.add("");
        out.add("        String sourceAt(int pc) {");
        sourceSwitch(out, "            ", cases, false, "null");
        out.add("        }");
        out.add("");
        out.add("        String sourceOfCallIn(int pc) {");
        sourceSwitch(out, "            ", cases, true, "sourceAt(pc)");
        out.add("        }");
        out.add("    }");
    }

    /** An overriding method that calls the method of the part that holds {@code pc}. */
    private void dispatch(JavaLines out, String signature, String partMethod, String otherwise) {
        out.add("    @Override");
        out.add("    protected " + signature + " {");
        String keyword = "if";
        for (Part part : parts) {
            out.add("        " + keyword + " (pc < " + part.end() + ") {");
            out.add("            return from" + part.first() + "." + partMethod + "(pc);");
            keyword = "} else if";
        }
        out.add("        }");
        out.add("        return " + otherwise + ";");
        out.add("    }");
    }

    /**
     * {@code return switch (pc) { ... };}: each case's comment, or ({@code ofCall}) the statement whose
     * call ends it where that differs.
     */
    private static void sourceSwitch(JavaLines out, String margin, List<CaseWriter.Case> cases, boolean ofCall,
            String otherwise) {
        out.add(margin + "return switch (pc) {");
        StringBuilder text = out.buffer();
        for (CaseWriter.Case c : cases) {
            String source = ofCall ? c.callSource() : c.comment();
            if (source != null) {
                JavaText.quote(text.append(margin).append("    case ").append(c.number()).append(" -> "), source)
                        .append(";\n");
            }
        }
        out.add(margin + "    default -> " + otherwise + ";");
        out.add(margin + "};");
    }
}
