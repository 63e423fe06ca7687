package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.atomic.AtomicReference;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.diagnostic.Diagnostic;
import masl.runtime.diagnostic.DiagnosticPrinter;
import masl.sim.xode.SecureXmlReader;
import masl.sim.xode.SourceLocation;
import masl.sim.xode.XodeException;
import masl.sim.xode.XodeLoader;
import masl.sim.xode.XodeProblem;
import masl.sim.xode.XodeSource;
import masl.translator.Frontend;
import masl.translator.MaslClassPath;
import masl.translator.Translation;
import masl.translator.Translator;
import masl.translator.compile.GeneratedCodeException;
import masl.translator.compile.InMemoryCompiler;
import masl.translator.source.SourceFile;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Bad input never crashes masl: the example programs (E1 to E8, the missions; 200 mutants
 * each) and the shipped descriptors (250 each), mutated with a seeded {@link Random} (tokens and
 * lines deleted, duplicated and swapped, random bytes written over or inserted, the text cut short),
 * are translated (or, for a descriptor, analysed with a program importing it): nothing may throw,
 * and a mutant that fails has only positioned diagnostics ({@code file:line:col}). Generated programs
 * at the edges of what Java holds (names, escapes, numbers, sizes, depths) must also
 * compile when they translate, and generated XODE nested up to and past the loader's limit must
 * load or be refused with located problems. A failing case is written to {@code build/fuzz/} to be
 * replayed with {@code masl check}.
 */
@Timeout(120)
@Tag("slow")
class FuzzTest {

    private static final long SEED = 20261123L;
    private static final int CASES_PER_PROGRAM = 200;
    private static final int CASES_PER_DESCRIPTOR = 250;
    private static final Pattern TOKEN = Pattern.compile("\"(?:[^\"\\\\\\n]|\\\\.)*\"|[A-Za-z_][A-Za-z_0-9]*|\\d+(?:\\.\\d+)?|\\S");

    @TempDir
    Path folder;

    @Test
    void mutatedProgramsGiveOnlyPositionedDiagnostics() throws IOException {
        List<Path> programs;
        try (Stream<Path> examples = Files.list(Path.of("src/test/resources/examples"));
                Stream<Path> missions = Files.list(Path.of("missions"))) {
            programs = Stream.concat(examples, missions).filter(file -> file.toString().endsWith(".masl")).sorted().toList();
        }
        assertTrue(programs.size() >= 10, programs::toString);
        Translator translator = new Translator(AgentPath.parse(""));
        Random random = new Random(SEED);
        for (Path program : programs) {
            String original = Files.readString(program);
            String name = program.getFileName().toString();
            for (int i = 0; i < CASES_PER_PROGRAM; i++) {
                String mutant = mutate(original, random);
                Translation translation;
                try {
                    translation = translator.translate(SourceFile.of(name, mutant));
                } catch (RuntimeException | StackOverflowError crash) {
                    throw new AssertionError(keep(name, i, mutant) + " crashed masl", crash);
                }
                if (!translation.succeeded()) {
                    assertPositioned(translation.diagnostics().sorted(), name, i, mutant);
                    assertPrintedWithPositions(translation.diagnostics().sorted(), name, i, mutant);
                }
            }
        }
    }

    @Test
    void mutatedDescriptorsGiveOnlyPositionedDiagnostics() throws IOException {
        List<Path> descriptors;
        try (Stream<Path> shipped = Files.list(Path.of("agents/src/main/resources"))) {
            descriptors = shipped.filter(file -> file.toString().endsWith(".xml")).sorted().toList();
        }
        assertTrue(descriptors.size() >= 3, descriptors::toString);
        Random random = new Random(SEED + 1);
        for (Path descriptor : descriptors) {
            String original = Files.readString(descriptor);
            String name = descriptor.getFileName().toString();
            String type = name.substring(0, name.length() - ".xml".length());
            Path program = folder.resolve("uses" + type + ".masl");
            Files.writeString(program, "import " + name + " as T;\nT one = newAgent(T);\nscalar entry main (true) { .nop(); }\n");
            for (int i = 0; i < CASES_PER_DESCRIPTOR; i++) {
                String mutant = mutate(original, random);
                Files.write(folder.resolve(name), mutant.getBytes(StandardCharsets.ISO_8859_1));
                Frontend.Result result;
                try {
                    // A new front end each time: the descriptor loader caches what it read.
                    result = new Frontend(AgentPath.parse("")).analyse(SourceFile.read(program));
                } catch (RuntimeException | StackOverflowError crash) {
                    throw new AssertionError(keep(name, i, mutant) + " crashed masl", crash);
                }
                if (!result.succeeded()) {
                    assertPositioned(result.diagnostics().sorted(), name, i, mutant);
                }
            }
        }
    }

    /**
     * Programs at the edges of what Java holds: names, escapes, numbers, sizes, depths
     * ({@link EdgePrograms}). Each translates to Java that javac compiles and whose mission class
     * loads, or fails with positioned diagnostics only. The Java of all of them is compiled at once;
     * if javac refuses it, each program is compiled alone to name the one at fault.
     */
    @Test
    @Timeout(120)
    void edgeProgramsCompileOrGiveOnlyPositionedDiagnostics() throws IOException {
        EdgePrograms generator = new EdgePrograms(new Random(SEED + 2));
        Translator translator = new Translator(AgentPath.parse(""));
        Map<Translation, String> compilable = new LinkedHashMap<>();
        int i = 0;
        for (EdgePrograms.Edge edge : EdgePrograms.Edge.values()) {
            for (int k = 0; k < casesOf(edge); k++, i++) {
                String name = "edge" + i + "-" + edge.name().toLowerCase(Locale.ROOT) + ".masl";
                String program = generator.program(edge);
                Translation translation;
                try {
                    translation = translator.translate(SourceFile.of(name, program));
                } catch (RuntimeException | Error crash) {
                    throw new AssertionError(keepUtf8(name, program) + " crashed masl", crash);
                }
                if (translation.succeeded()) {
                    compilable.put(translation, program);
                } else {
                    assertPositioned(translation.diagnostics().sorted(), name, i, program);
                    assertPrintedWithPositions(translation.diagnostics().sorted(), name, i, program);
                }
            }
        }
        assertTrue(compilable.size() >= i / 3, "most edge programs are valid: " + compilable.size() + " of " + i);
        try {
            compileAndLoad(compilable.keySet());
        } catch (GeneratedCodeException | LinkageError | ReflectiveOperationException together) {
            for (Map.Entry<Translation, String> one : compilable.entrySet()) {
                try {
                    compileAndLoad(List.of(one.getKey()));
                } catch (GeneratedCodeException | LinkageError | ReflectiveOperationException alone) {
                    throw new AssertionError(keepUtf8(one.getKey().source().name(), one.getValue())
                            + ": javac or the JVM refused its Java", alone);
                }
            }
            throw new AssertionError("the edge programs' Java fails together, not alone", together);
        }
    }

    private static int casesOf(EdgePrograms.Edge edge) {
        return switch (edge) {
            case NAMES, ESCAPES -> 10;
            case NUMBERS -> 6;
            case SIZES, DEPTHS -> 4;
        };
    }

    /**
     * Compiles the translations' Java in one run of javac and initialises each mission class, on a
     * thread with a deep stack as {@code MissionLoader} does: javac recurses into nested code too.
     */
    private static void compileAndLoad(Collection<Translation> translations) throws ReflectiveOperationException {
        List<InMemoryCompiler.Source> sources = new ArrayList<>();
        for (Translation translation : translations) {
            translation.javaSources().forEach((className, text) -> sources.add(new InMemoryCompiler.Source(className, text)));
        }
        AtomicReference<Throwable> failure = new AtomicReference<>();
        Thread javac = new Thread(null, () -> {
            try {
                ClassLoader loaded = new InMemoryCompiler(MaslClassPath.runtimeAndShippedAgents())
                        .compile(sources, FuzzTest.class.getClassLoader());
                for (Translation translation : translations) {
                    Class.forName(translation.missionClassName(), true, loaded);
                }
            } catch (Throwable e) {
                failure.set(e);
            }
        }, "javac", 256L * 1024 * 1024);
        javac.start();
        try {
            javac.join();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AssertionError(e);
        }
        Throwable thrown = failure.get();
        if (thrown instanceof ReflectiveOperationException reflective) {
            throw reflective;
        }
        if (thrown instanceof RuntimeException runtime) {
            throw runtime;
        }
        if (thrown instanceof Error error) {
            throw error;
        }
    }

    /**
     * Random XODE documents nested up to and past the loader's limit, with attributes full of XML
     * escapes: each loads or is refused with located problems, whatever the caller's stack.
     */
    @Test
    @Timeout(120)
    void generatedXodeGivesOnlyLocatedProblems() throws IOException {
        Random random = new Random(SEED + 3);
        List<String> elements = List.of("group", "body", "space", "geom", "mass", "jointgroup", "transform", "unknown");
        List<String> values = List.of("1", "-0", "1e999", "NaN", "&#10;", "&#0;", "&lt;&amp;", "a&#x1F600;b", "\\u0022");
        for (int i = 0; i < 30; i++) {
            int depth = switch (i % 3) {
                case 0 -> 1 + random.nextInt(50);
                case 1 -> 1_990 + random.nextInt(20);
                default -> SecureXmlReader.DEEPEST - 10 + random.nextInt(20);
            };
            StringBuilder xml = new StringBuilder("<xode version=\"1.0r23\" name=\"t\"><world><space name=\"s\">\n");
            List<String> open = new ArrayList<>();
            for (int d = 0; d < depth; d++) {
                String element = elements.get(random.nextInt(elements.size()));
                xml.append('<').append(element).append(" name=\"e").append(d).append("\" radius=\"")
                        .append(values.get(random.nextInt(values.size()))).append("\">\n");
                open.add(element);
            }
            for (int d = open.size() - 1; d >= 0; d--) {
                xml.append("</").append(open.get(d)).append(">\n");
            }
            xml.append("</space></world></xode>\n");
            String name = "generated" + i + ".xode";
            try {
                new XodeLoader().load(XodeSource.text(name, xml.toString()));
            } catch (XodeException refused) {
                for (XodeProblem problem : refused.problems()) {
                    SourceLocation at = problem.location();
                    if (!at.file().equals(name) || at.line() < 1 || at.column() < 1 || problem.message().isBlank()) {
                        throw new AssertionError(keepUtf8(name, xml.toString()) + ": a problem without a location: "
                                + problem);
                    }
                }
            } catch (RuntimeException | Error crash) {
                throw new AssertionError(keepUtf8(name, xml.toString()) + " crashed the XODE loader", crash);
            }
        }
    }

    private static void assertPositioned(List<Diagnostic> diagnostics, String name, int i, String mutant) throws IOException {
        assertFalse(diagnostics.isEmpty(), () -> "case " + i + " of " + name + " failed without a diagnostic");
        for (Diagnostic diagnostic : diagnostics) {
            if (diagnostic.file() == null || diagnostic.file().isEmpty() || diagnostic.line() < 1 || diagnostic.column() < 1
                    || diagnostic.message() == null || diagnostic.message().isBlank()) {
                throw new AssertionError(keep(name, i, mutant) + ": a diagnostic without a position: " + diagnostic);
            }
        }
    }

    /** What {@code masl check} prints: each error's headline is {@code file:line:col: error: …}, then its line and a caret. */
    private static void assertPrintedWithPositions(List<Diagnostic> diagnostics, String name, int i, String mutant)
            throws IOException {
        String report;
        try {
            report = new DiagnosticPrinter(Map.of(name, mutant)).report(diagnostics);
        } catch (RuntimeException crash) {
            throw new AssertionError(keep(name, i, mutant) + " crashed the diagnostics' printer", crash);
        }
        // DOTALL: a message may quote the mutant's text, which may hold characters such as U+0085.
        Pattern headline = Pattern.compile(Pattern.quote(name) + ":\\d+:\\d+: (error|warning): .+", Pattern.DOTALL);
        long headlines = report.lines().filter(line -> headline.matcher(line).matches()).count();
        if (headlines != diagnostics.size()) {
            throw new AssertionError(keep(name, i, mutant) + ": " + diagnostics.size() + " diagnostics but "
                    + headlines + " positioned headlines in\n" + report);
        }
    }

    /** Writes a failing generated case to build/fuzz/ in UTF-8 and names it. */
    private static String keepUtf8(String name, String text) throws IOException {
        Path kept = Files.createDirectories(Path.of("build/fuzz")).resolve(name);
        Files.writeString(kept, text);
        return name + " (kept in " + kept + ")";
    }

    /** Writes a failing case to build/fuzz/ and names it. */
    private static String keep(String name, int i, String mutant) throws IOException {
        Path kept = Files.createDirectories(Path.of("build/fuzz")).resolve(i + "-" + name);
        Files.write(kept, mutant.getBytes(StandardCharsets.ISO_8859_1));
        return "case " + i + " of " + name + " (kept in " + kept + ")";
    }

    /** One to three mutations of {@code text}. */
    static String mutate(String text, Random random) {
        String mutant = text;
        int mutations = 1 + random.nextInt(3);
        for (int m = 0; m < mutations; m++) {
            mutant = switch (random.nextInt(9)) {
                case 0 -> tokens(mutant, random, Edit.DELETE);
                case 1 -> tokens(mutant, random, Edit.DUPLICATE);
                case 2 -> tokens(mutant, random, Edit.SWAP);
                case 3 -> lines(mutant, random, Edit.DELETE);
                case 4 -> lines(mutant, random, Edit.DUPLICATE);
                case 5 -> lines(mutant, random, Edit.SWAP);
                case 6 -> randomBytes(mutant, random, true);
                case 7 -> randomBytes(mutant, random, false);
                default -> mutant.substring(0, random.nextInt(mutant.length() + 1));
            };
        }
        return mutant;
    }

    private enum Edit { DELETE, DUPLICATE, SWAP }

    /** Edits one token (or swaps two): pieces are the tokens and what lies between them. */
    private static String tokens(String text, Random random, Edit edit) {
        List<int[]> spans = new ArrayList<>();
        Matcher token = TOKEN.matcher(text);
        while (token.find()) {
            spans.add(new int[] {token.start(), token.end()});
        }
        if (spans.isEmpty()) {
            return text;
        }
        int[] a = spans.get(random.nextInt(spans.size()));
        String first = text.substring(a[0], a[1]);
        return switch (edit) {
            case DELETE -> text.substring(0, a[0]) + text.substring(a[1]);
            case DUPLICATE -> text.substring(0, a[1]) + " " + first + text.substring(a[1]);
            case SWAP -> {
                int[] b = spans.get(random.nextInt(spans.size()));
                if (b[0] == a[0]) {
                    yield text;
                }
                int[] lo = a[0] < b[0] ? a : b;
                int[] hi = a[0] < b[0] ? b : a;
                yield text.substring(0, lo[0]) + text.substring(hi[0], hi[1]) + text.substring(lo[1], hi[0])
                        + text.substring(lo[0], lo[1]) + text.substring(hi[1]);
            }
        };
    }

    private static String lines(String text, Random random, Edit edit) {
        List<String> lines = new ArrayList<>(List.of(text.split("\n", -1)));
        int i = random.nextInt(lines.size());
        switch (edit) {
            case DELETE -> lines.remove(i);
            case DUPLICATE -> lines.add(i, lines.get(i));
            case SWAP -> {
                int j = random.nextInt(lines.size());
                String line = lines.get(i);
                lines.set(i, lines.get(j));
                lines.set(j, line);
            }
        }
        return String.join("\n", lines);
    }

    /** One to eight random bytes (any of 0 to 255, as ISO-8859-1 characters) written over the text or inserted. */
    private static String randomBytes(String text, Random random, boolean overwrite) {
        StringBuilder mutant = new StringBuilder(text);
        int count = 1 + random.nextInt(8);
        int at = random.nextInt(mutant.length() + 1);
        for (int k = 0; k < count; k++) {
            char c = (char) random.nextInt(256);
            if (overwrite && at + k < mutant.length()) {
                mutant.setCharAt(at + k, c);
            } else {
                mutant.insert(Math.min(at + k, mutant.length()), c);
            }
        }
        return mutant.toString();
    }
}
