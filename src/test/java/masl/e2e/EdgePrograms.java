package masl.e2e;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import java.util.stream.Collectors;
import java.util.stream.IntStream;
import masl.translator.parse.Nesting;

/**
 * Random MASL programs at the edges of what the generated Java can hold, for {@link FuzzTest}:
 * names that are the generated code's own or Java's, literals full of escapes, numbers at and past
 * their type's limits, programs of thousands of statements, blocks, declarations, events or agents,
 * and constructs nested around the depths masl translates. Each program is valid MASL unless an edge
 * makes it invalid, which must then be a positioned error.
 */
final class EdgePrograms {

    enum Edge { NAMES, ESCAPES, NUMBERS, SIZES, DEPTHS }

    /** Names a demanding user may give a type, an agent, a block, a variable or an event. */
    private static final List<String> NAMES = List.of("Agent", "Mission", "AgentProgram", "MissionProgram", "URI",
            "List", "Types", "Label", "Event", "Reaction", "Objects", "String", "Integer", "Math", "System", "self",
            "pc", "ctx", "agents", "population", "builder", "AGENTS", "LOADER", "MAIN", "tmp$1", "keep$main",
            "agent$a", "a$b", "b$c", "main$x", "java", "masl", "lang", "record", "yield", "var", "_x", "$", "é",
            "straße", "int_", "Default", "AgentContext", "CompletableFuture", "invoke$logln", "resumeFrom0",
            "Structure2", "sourceAt", "resume", "reactionPc", "goOn", "Mode", "uri", "load", "specs", "create");

    /** Pieces of literals and comments: escapes of every kind, and characters javac reads specially. */
    private static final List<String> PIECES = List.of("a", " ", "\\n", "\\t", "\\\\", "\\\"", "\\'", "\\0", "\\7",
            "\\377", "\\u0041", "\\u000a", "\\u000d", "\\u0022", "\\u0027", "\\u005c", "\\uuu005c", "\\ud83d", "\\ude00",
            "\\u002a\\u002f", "é", "😀", "*/", "/*", "//", "\u2028", "\\u00e9", "\\u0000", "\\uffff");

    /** The contents of a character literal: most hold one char, a few do not. */
    private static final List<String> CHARACTERS = List.of("a", "\\n", "\\\\", "\\'", "\"", "\\0", "\\377",
            "\\u0041", "\\u0027", "\\u005c", "é", "\\uffff", "\\ud83d", "😀", "ab", "\u2028");

    private static final List<String> NUMBERS = List.of("2147483647", "2147483648", "-2147483648", "0x7fff_ffff",
            "0xFFFFFFFF", "0x1_0000_0000", "037777777777", "040000000000", "09", "0_7",
            "0b11111111111111111111111111111111", "0b111111111111111111111111111111111", "1e308", "1e309", "1e-323",
            "1e-400", "0.0e-999", "3.4e38f", "3.5e38f", "1.4e-45f", "1e-46f", "9223372036854775807L",
            "9223372036854775808L", "-9223372036854775808L", "0x7FFF_FFFF_FFFF_FFFFL", "0x1_0000_0000_0000_0000L");

    private final Random random;

    EdgePrograms(Random random) {
        this.random = random;
    }

    String program(Edge edge) {
        return switch (edge) {
            case NAMES -> names();
            case ESCAPES -> escapes();
            case NUMBERS -> numbers();
            case SIZES -> sizes();
            case DEPTHS -> depths();
        };
    }

    /** Each role a distinct name: a clash between two roles is the program's error, not an edge. */
    private String names() {
        List<String> shuffled = new ArrayList<>(NAMES);
        Collections.shuffle(shuffled, random);
        String type = shuffled.get(0);
        String agent = shuffled.get(1);
        String other = shuffled.get(2);
        String block = shuffled.get(3);
        String local = shuffled.get(4);
        String inner = shuffled.get(5);
        String shared = shuffled.get(6);
        String event = shuffled.get(7);
        String declared = random.nextBoolean() ? "import Default.xml as " + type + ";\n" : "type " + type + " use Default.xml;\n";
        return declared + type + " " + agent + ", " + other + " = newAgent(" + type + ");\n"
                + "asynchronous entry main (true) {\n"
                + "  shared event " + event + ";\n"
                + "  local int " + local + " = 1;\n"
                + "  shared int " + shared + " = 2;\n"
                + "  scalar entry " + block + " (true) {\n"
                + "    local int " + inner + " = 3;\n"
                + "    " + inner + "++;\n"
                + "    if (" + inner + " > 100) reelect(" + block + ");\n"
                + "    .logln(" + inner + " + " + local + ");\n"
                + "  }\n"
                + "  " + shared + " += " + local + ";\n"
                + "  emit(" + event + ");\n"
                + "  .nop();\n"
                + "  react (" + event + ") { .logln(\"" + event + "\"); resume; }\n"
                + "}\n";
    }

    /** One string, one character and one comment of random pieces. */
    private String escapes() {
        return header() + "scalar entry main (true) {\n"
                + "  .logln(\"" + literal(1 + random.nextInt(3)) + "\"); // " + literal(3) + "\n"
                + "  .logln('" + pick(CHARACTERS) + "'); /* " + literal(2) + " */\n"
                + "}\n";
    }

    /** One number, and a count of loops to leave. */
    private String numbers() {
        String number = pick(NUMBERS);
        String type = number.endsWith("f") ? "float" : number.endsWith("L") ? "long"
                : number.contains("e") || number.contains(".") ? "double" : "int";
        return header() + "scalar entry main (true) {\n"
                + "  local " + type + " n = " + number + ";\n"
                + "  .logln(n);\n"
                + "  while (true) { exit(" + pick(List.of("1", "0x1", "01", "0b1", "1_0", "99999999999")) + "); }\n"
                + "}\n";
    }

    private String sizes() {
        int count = 1_000 + random.nextInt(2_500);
        StringBuilder body = new StringBuilder();
        switch (random.nextInt(5)) {
            case 0 -> IntStream.range(0, count).forEach(i -> body.append("  .logln(\"s").append(i).append("\");\n"));
            case 1 -> {
                IntStream.range(0, count).forEach(i -> body.append("  local int v").append(i).append(" = ").append(i).append(";\n"));
                body.append("  .logln(v").append(count - 1).append(");\n");
            }
            case 2 -> IntStream.range(0, count / 2).forEach(i -> body.append("  scalar entry b").append(i)
                    .append(" (true) { .logln(").append(i).append("); }\n"));
            case 3 -> {
                IntStream.range(0, count / 2).forEach(i -> body.append("  shared event e").append(i).append(";\n"));
                body.append("  emit(e0);\n  .nop();\n");
                IntStream.range(0, count / 2).forEach(i -> body.append("  react (e").append(i).append(") { resume; }\n"));
            }
            default -> body.append("  .logln(\"").append("ü".repeat(32_000 + random.nextInt(1_500))).append("\");\n");
        }
        String agents = IntStream.range(0, 1 + random.nextInt(20_000)).mapToObj(i -> "a" + i)
                .collect(Collectors.joining(", "));
        return "import Default.xml as Default;\nDefault " + agents + " = newAgent(Default);\n"
                + "asynchronous entry main (.getProxyID() == 0) {\n" + body + "}\n";
    }

    /** One construct nested about 2,000 deep, or just within or past masl's limit. */
    private String depths() {
        int depth = switch (random.nextInt(3)) {
            case 0 -> 1_990 + random.nextInt(20);
            case 1 -> Nesting.DEEPEST / 3 - 5 + random.nextInt(10);
            default -> Nesting.DEEPEST - 10 + random.nextInt(20);
        };
        String statement = switch (random.nextInt(7)) {
            case 0 -> "  .logln(" + "(".repeat(depth) + "1" + ")".repeat(depth) + ");\n";
            case 1 -> "  .logln(" + IntStream.range(0, depth).mapToObj(i -> "1").collect(Collectors.joining(" + ")) + ");\n";
            case 2 -> "  .logln(" + "!".repeat(depth) + "true);\n";
            case 3 -> "  " + "{".repeat(depth) + ".logln(1);" + "}".repeat(depth) + "\n";
            case 4 -> "  " + IntStream.range(0, depth / 2).mapToObj(i -> "if (.getProxyID() == " + i + ") { .nop(); }")
                    .collect(Collectors.joining(" else ")) + "\n";
            case 5 -> "  " + "if (true) ".repeat(depth) + ".logln(1);\n";
            default -> IntStream.range(0, depth / 3).mapToObj(i -> "  scalar entry b" + i + " (true) {\n")
                    .collect(Collectors.joining()) + "  .logln(1);\n" + "  }\n".repeat(depth / 3);
        };
        return header() + "scalar entry main (true) {\n" + statement + "}\n";
    }

    private static String header() {
        return "import Default.xml as Default;\nDefault a, b = newAgent(Default);\n";
    }

    /** The source of a literal's content: {@code pieces} random pieces. */
    private String literal(int pieces) {
        StringBuilder text = new StringBuilder();
        for (int i = 0; i < pieces; i++) {
            text.append(pick(PIECES));
        }
        return text.toString();
    }

    private <T> T pick(List<T> from) {
        return from.get(random.nextInt(from.size()));
    }
}
