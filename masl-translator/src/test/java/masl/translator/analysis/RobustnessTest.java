package masl.translator.analysis;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import masl.translator.source.SourceFile;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The analysis never throws on a program that parsed: it is run on every corpus program with each of its
 * lines blanked in turn, which leaves programs with undeclared names, missing blocks, broken headers, ….
 */
class RobustnessTest {

    static Stream<Path> corpus() throws IOException {
        return CorpusAnalysisTest.corpus();
    }

    @ParameterizedTest
    @MethodSource("corpus")
    void programWithAnyOneLineBlankedIsAnalysedWithoutException(Path program) throws IOException {
        List<String> lines = Files.readAllLines(program);
        int semanticallyWrong = 0;
        for (int blanked = 0; blanked < lines.size(); blanked++) {
            List<String> mutilated = new ArrayList<>(lines);
            mutilated.set(blanked, "");
            SourceFile source = new SourceFile("line-" + (blanked + 1) + ".masl", Analysis.FIXTURES,
                    String.join("\n", mutilated));
            Analysis.Result result = assertDoesNotThrow(() -> Analysis.analyze(source), source.name());
            boolean analysed = !result.program().types().isEmpty();
            if (analysed && !result.diagnostics().isEmpty()) {
                semanticallyWrong++;
            }
        }
        // Blanking the first import leaves a program the analysis rejects: the mutants do reach the analysis.
        assertTrue(semanticallyWrong > 0, program.toString());
    }
}
