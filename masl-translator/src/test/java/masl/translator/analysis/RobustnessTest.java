package masl.translator.analysis;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import masl.translator.source.SourceFile;
import org.junit.jupiter.api.Test;

/**
 * The analysis never throws on a program that parsed: it is run on every corpus program with each of its
 * lines removed in turn, which leaves programs with undeclared names, missing blocks, broken headers, ….
 */
class RobustnessTest {

    private static final Path PROGRAM = Path.of("..", "masl-grammar", "src", "test", "resources", "corpus",
            "every-production.masl");

    @Test
    void everyProgramWithOneLineRemovedIsAnalysedWithoutException() throws IOException {
        List<String> lines = Files.readAllLines(PROGRAM);
        int analysedWithErrors = 0;
        for (int removed = 0; removed < lines.size(); removed++) {
            List<String> mutilated = new ArrayList<>(lines);
            mutilated.set(removed, "");
            SourceFile source = new SourceFile("line-" + (removed + 1) + ".masl", Analysis.FIXTURES,
                    String.join("\n", mutilated));
            Analysis.Result result = assertDoesNotThrow(() -> Analysis.analyze(source), source.name());
            if (!result.diagnostics().isEmpty()) {
                analysedWithErrors++;
            }
        }
        assertTrue(analysedWithErrors >= 10, "removing a declaration line breaks the program: " + analysedWithErrors);
    }
}
