package masl.translator.analysis;

import static org.junit.jupiter.api.Assertions.assertFalse;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import masl.translator.source.SourceFile;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Every program of the grammar's corpus (the examples of examples.md and every-production.masl) analyses
 * without an error. They are read as if they stood in the fixtures' folder, where their descriptors are.
 */
class CorpusAnalysisTest {

    private static final Path CORPUS = Path.of("..", "masl-grammar", "src", "test", "resources", "corpus");

    static Stream<Path> corpus() throws IOException {
        try (Stream<Path> files = Files.list(CORPUS)) {
            return files.filter(file -> file.toString().endsWith(".masl")).sorted().toList().stream();
        }
    }

    @ParameterizedTest
    @MethodSource("corpus")
    void analysesWithoutError(Path program) throws IOException {
        String name = program.getFileName().toString();
        SourceFile source = new SourceFile(name, Analysis.FIXTURES, Files.readString(program));
        Analysis.Result result = Analysis.analyze(source);
        result.assertNoError();
        assertFalse(result.program().agents().isEmpty());
    }
}
