package masl.e2e;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicContainer;
import org.junit.jupiter.api.DynamicNode;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;
import org.junit.jupiter.api.Timeout;

/**
 * The manual cannot drift from the code: every page of docs/manual, found by listing the folder so
 * that a page added later is covered, has each of its MASL programs run (or checked) by the
 * {@code masl} command, against the journal (or the errors) shown under it (docs/manual/README.md,
 * "Programs in this manual are tested").
 */
@Timeout(300)
class ManualTest {

    private static final Path MANUAL = Path.of("docs/manual");
    private static final Path WORK = Path.of("build/manual");

    @TestFactory
    Stream<DynamicNode> everyProgramOfTheManualGivesWhatItShows() throws IOException {
        List<Path> pages;
        try (Stream<Path> files = Files.list(MANUAL)) {
            pages = files.filter(file -> file.toString().endsWith(".md")).sorted().toList();
        }
        if (pages.isEmpty()) {
            throw new AssertionError("no page in " + MANUAL.toAbsolutePath());
        }
        return pages.stream().map(ManualTest::page);
    }

    private static DynamicNode page(Path file) {
        ManualPage page = ManualPage.read(file);
        Path folder = WORK.resolve(page.name().replace(".md", "")).toAbsolutePath();
        return DynamicContainer.dynamicContainer(page.name(), ManualExamples.of(page, folder).stream()
                .map(check -> DynamicTest.dynamicTest(check.where(), check.verify()::run)));
    }
}
