package masl.runtime.descriptor;

import static masl.runtime.descriptor.TestDescriptors.agent;
import static masl.runtime.descriptor.TestDescriptors.assertSingleProblem;
import static masl.runtime.descriptor.TestDescriptors.problemsOf;
import static masl.runtime.descriptor.TestDescriptors.write;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import masl.runtime.diagnostic.Diagnostic;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code <Fipa>}: a type answered by an external FIPA agent, found by service type or by name. */
class FipaBindingTest {

    private static final String ROBOT = "masl.runtime.descriptor.fixtures.Robot";

    @TempDir
    Path folder;

    private Path file() {
        return folder.resolve("T.xml");
    }

    private List<Diagnostic> problems(String body) {
        Path file = write(folder, "T.xml", agent(ROBOT, body));
        return problemsOf(() -> TestDescriptors.loader().load(file));
    }

    private AgentType load(String body) {
        return TestDescriptors.loader().load(write(folder, "T.xml", agent(ROBOT, body)));
    }

    @Test
    void aTypeIsBoundByServiceTypeOrByNameWithItsLanguageAndOntology() {
        assertEquals(Optional.of(new FipaBinding("calculator", null, "json", "arithmetic")),
                load("  <Fipa service_type=\"calculator\" language=\"json\" ontology=\"arithmetic\"/>\n").fipa());
        assertEquals(Optional.of(new FipaBinding(null, "greeter@p", "string", null)),
                load("  <Fipa agent_name=\"greeter@p\" language=\"string\"/>\n").fipa());
        assertEquals(Optional.empty(), load("").fipa());
    }

    @Test
    void aFipaElementNamesItsAgentOneWay() {
        assertSingleProblem(problems("  <Fipa language=\"json\"/>\n"), file(), 3, 3,
                "<Fipa> names its agent by service_type or by agent_name: give one of the two");
        assertSingleProblem(problems("  <Fipa service_type=\"s\" agent_name=\"a\" language=\"json\"/>\n"), file(), 3, 3,
                "give one of the two");
    }

    @Test
    void aTypeHasOneFipaElementAtMost() {
        assertSingleProblem(problems("  <Fipa agent_name=\"a\" language=\"json\"/>\n"
                + "  <Fipa agent_name=\"b\" language=\"json\"/>\n"), file(), 4, 3,
                "a type has one <Fipa> at most: the first is on line 3");
    }

    @Test
    void theContentLanguageIsJsonOrString() {
        assertSingleProblem(problems("  <Fipa agent_name=\"a\" language=\"sl\"/>\n"), file(), 3, 3, "language", "sl");
    }
}
