package masl.runtime.descriptor;

import static masl.runtime.descriptor.TestDescriptors.problemsOf;
import static masl.runtime.descriptor.TestDescriptors.write;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import masl.runtime.diagnostic.Diagnostic;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** No DTD is fetched or applied, no external entity is expanded (agent-types.md, first rule). */
class SecureReadingTest {

    private static final String SECRET = "TOP-SECRET-CONTENT";

    @TempDir
    Path folder;

    @Test
    void doctypeNamingAnHttpDtdIsIgnoredAndNothingIsFetched() throws IOException {
        AtomicInteger connections = new AtomicInteger();
        try (ServerSocket server = new ServerSocket(0)) {
            Thread listener = new Thread(() -> {
                try (Socket ignored = server.accept()) {
                    connections.incrementAndGet();
                } catch (IOException closed) {
                    // The test closed the server: nobody connected.
                }
            });
            listener.start();
            Path file = write(folder, "Old.xml", """
                    <?xml version="1.0"?>
                    <!DOCTYPE Agent SYSTEM "http://127.0.0.1:%d/agent.dtd">
                    <Agent short_class_name="Old" full_class_name="masl.runtime.descriptor.fixtures.Robot"/>
                    """.formatted(server.getLocalPort()));
            AgentType old = TestDescriptors.loader().load(file);
            assertEquals("Old", old.shortName());
            assertEquals(3, old.line());
        }
        assertEquals(0, connections.get(), "the DTD was fetched");
    }

    @Test
    void schemaLocationHintsAreAcceptedAndNotFollowed() {
        // Were the hinted schema read, it would be an error: it is not a schema.
        write(folder, "other.xsd", "not a schema");
        Path file = write(folder, "Hinted.xml", """
                <?xml version="1.0"?>
                <Agent xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance" xsi:noNamespaceSchemaLocation="other.xsd"
                       short_class_name="Hinted" full_class_name="masl.runtime.descriptor.fixtures.Robot"/>
                """);
        assertEquals("Hinted", TestDescriptors.loader().load(file).shortName());
    }

    @Test
    void doctypeNamingALocalDtdIsNotApplied() {
        // Were this DTD read, it would fix short_class_name to "Hacked" or make the file invalid.
        write(folder, "evil.dtd", """
                <!ELEMENT Agent (Nothing)>
                <!ATTLIST Agent short_class_name CDATA #FIXED "Hacked" injected CDATA "yes">
                """);
        Path file = write(folder, "Old.xml", """
                <?xml version="1.0"?>
                <!DOCTYPE Agent SYSTEM "evil.dtd">
                <Agent full_class_name="masl.runtime.descriptor.fixtures.Robot" short_class_name="Old"/>
                """);
        AgentType old = TestDescriptors.loader().load(file);
        assertEquals("Old", old.shortName());
    }

    @Test
    void externalEntityInAnAttributeIsNotExpanded() {
        Path secret = write(folder, "secret.txt", SECRET);
        Path file = write(folder, "Xxe.xml", """
                <?xml version="1.0"?>
                <!DOCTYPE Agent [<!ENTITY x SYSTEM "%s">]>
                <Agent short_class_name="&x;" full_class_name="masl.runtime.descriptor.fixtures.Robot"/>
                """.formatted(secret.toUri()));
        List<Diagnostic> problems = problemsOf(() -> TestDescriptors.loader().load(file));
        assertRefused(problems, file, 3);
    }

    @Test
    void externalEntityInContentIsNotExpanded() {
        Path secret = write(folder, "secret.txt", SECRET);
        Path file = write(folder, "Xxe.xml", """
                <?xml version="1.0"?>
                <!DOCTYPE Agent [<!ENTITY x SYSTEM "%s">]>
                <Agent short_class_name="X" full_class_name="masl.runtime.descriptor.fixtures.Robot">&x;</Agent>
                """.formatted(secret.toUri()));
        List<Diagnostic> problems = problemsOf(() -> TestDescriptors.loader().load(file));
        assertRefused(problems, file, 3);
    }

    @Test
    void internalEntitiesAreNotExpandedEither() {
        // The "billion laughs" family needs entity expansion: none happens.
        Path file = write(folder, "Laughs.xml", """
                <?xml version="1.0"?>
                <!DOCTYPE Agent [<!ENTITY a "ha"><!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;">]>
                <Agent short_class_name="&b;" full_class_name="masl.runtime.descriptor.fixtures.Robot"/>
                """);
        assertRefused(problemsOf(() -> TestDescriptors.loader().load(file)), file, 3);
    }

    private static void assertRefused(List<Diagnostic> problems, Path file, int line) {
        assertEquals(1, problems.size(), () -> TestDescriptors.render(problems));
        Diagnostic problem = problems.get(0);
        assertEquals(file.toString(), problem.file());
        assertEquals(line, problem.line());
        assertTrue(problem.message().contains("entity"), problem.message());
        assertFalse(problem.message().contains(SECRET), problem.message());
    }
}
