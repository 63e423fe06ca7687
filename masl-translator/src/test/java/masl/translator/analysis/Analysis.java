package masl.translator.analysis;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.net.URISyntaxException;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import masl.runtime.descriptor.AgentPath;
import masl.runtime.descriptor.DescriptorLoader;
import masl.runtime.diagnostic.Diagnostic;
import masl.translator.diagnostics.Diagnostics;
import masl.translator.parse.ProgramParser;
import masl.translator.source.SourceFile;

/**
 * Runs the analysis on program texts whose folder holds the fixture descriptors ({@code robots/Khepera.xml},
 * {@code robots/Explorer.xml}, {@code my robots/Robot.xml}); {@code Default.xml} comes from the classpath.
 */
final class Analysis {

    static final String FILE = "test.masl";
    static final Path FIXTURES = fixtures();
    private static final DescriptorLoader DESCRIPTORS = new DescriptorLoader(AgentPath.parse(""));

    /** The outcome of analysing one program. */
    record Result(AnalyzedProgram program, List<Diagnostic> diagnostics) {

        String rendered() {
            return diagnostics.stream().map(Diagnostic::headline).collect(Collectors.joining("\n"));
        }

        /** Asserts the one error the program has. */
        void assertError(int line, int column, String message) {
            assertEquals(FILE + ":" + line + ":" + column + ": error: " + message, rendered());
        }

        void assertNoError() {
            assertEquals("", rendered());
        }
    }

    private Analysis() {
    }

    static Result analyze(String text) {
        return analyze(new SourceFile(FILE, FIXTURES, text));
    }

    static Result analyze(SourceFile source) {
        Diagnostics diagnostics = new Diagnostics();
        ProgramParser.Parsed parsed = ProgramParser.parse(source, diagnostics);
        AnalyzedProgram program = Analyzer.analyze(parsed, DESCRIPTORS, diagnostics);
        return new Result(program, diagnostics.sorted());
    }

    /**
     * A program with the usual headers and {@code body} as the body of {@code asynchronous entry main}:
     * {@code body} starts on line 7, column 1.
     */
    static Result analyzeBody(String body) {
        return analyze(HEADERS + "asynchronous entry main (true) {\n" + body + "\n}\n");
    }

    /** Five lines: the fixture types and one agent of each. */
    static final String HEADERS = """
            import Default.xml;
            import robots/Khepera.xml;
            import robots/Explorer.xml;
            Default d = newAgent(Default);
            Khepera k = newAgent(Khepera);
            """;

    private static Path fixtures() {
        try {
            return Path.of(Analysis.class.getResource("/analysis/robots/Khepera.xml").toURI()).getParent().getParent();
        } catch (URISyntaxException impossible) {
            throw new IllegalStateException(impossible);
        }
    }
}
