package masl.runtime.descriptor;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.URISyntaxException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import masl.runtime.diagnostic.Diagnostic;
import org.junit.jupiter.api.function.Executable;

/** Shared by the descriptor tests: the fixture descriptors, a loader over them, problem assertions. */
final class TestDescriptors {

    /** The tests' root type, standing in for masl.agents.Default (see descriptors/Default.xml). */
    static final String FIXTURE_ROOT = "masl.runtime.descriptor.fixtures.Default";

    static final String PREFIX = "masl.runtime.descriptor.fixtures.";

    private TestDescriptors() {
    }

    /** The folder of the test resources' descriptors (Default.xml, Robot.xml, Khepera.xml). */
    static Path fixtureFolder() {
        try {
            return Path.of(TestDescriptors.class.getResource("/descriptors/Default.xml").toURI()).getParent();
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
    }

    /** A loader whose agent path is {@code entries} then the fixture folder, with the fixture root type. */
    static DescriptorLoader loader(Path... entries) {
        List<Path> path = new ArrayList<>(List.of(entries));
        path.add(fixtureFolder());
        return new DescriptorLoader(AgentPath.of(path, TestDescriptors.class.getClassLoader()), FIXTURE_ROOT);
    }

    static Path write(Path folder, String fileName, String content) {
        try {
            Path file = folder.resolve(fileName);
            Files.createDirectories(file.getParent());
            Files.writeString(file, content);
            return file;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** The problems of a loading that must fail. */
    static List<Diagnostic> problemsOf(Executable loading) {
        return assertThrows(DescriptorException.class, loading).problems();
    }

    /** Asserts there is exactly one problem, at {@code file:line:column}, whose message contains each fragment. */
    static Diagnostic assertSingleProblem(List<Diagnostic> problems, Path file, int line, int column,
            String... fragments) {
        assertEquals(1, problems.size(), () -> "expected one problem, got:\n" + render(problems));
        return assertProblem(problems.get(0), file, line, column, fragments);
    }

    static Diagnostic assertProblem(Diagnostic problem, Path file, int line, int column,
            String... fragments) {
        assertEquals(file.toString(), problem.file(), problem::toString);
        assertEquals(line, problem.line(), problem::toString);
        assertEquals(column, problem.column(), problem::toString);
        for (String fragment : fragments) {
            assertTrue(problem.message().contains(fragment),
                    () -> "message lacks \"" + fragment + "\": " + problem.message());
        }
        return problem;
    }

    static String render(List<Diagnostic> problems) {
        return String.join("\n", problems.stream().map(Diagnostic::toString).toList());
    }

    /** A minimal valid descriptor of the fixture root's subtype, with {@code body} inside {@code <Agent>}. */
    static String agent(String className, String body) {
        return "<?xml version=\"1.0\"?>\n"
                + "<Agent short_class_name=\"T\" full_class_name=\"" + className + "\">\n"
                + body
                + "</Agent>\n";
    }
}
