package masl.lsp;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.eclipse.lsp4j.Location;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/** Go to definition: names to their declarations, types to their imports, imports to descriptors. */
class DefinitionTest {

    private final Editor editor = new Editor();

    @AfterEach
    void close() {
        editor.close();
    }

    /** Asserts that the definition at the cursor of {@code program} is where {@code declaration} starts. */
    private void assertLeadsTo(String declaration, String program) {
        editor.open(program);
        List<? extends Location> found = editor.definition();
        assertEquals(1, found.size(), "a definition for " + declaration + " in\n" + program);
        assertEquals(editor.uri, found.get(0).getUri());
        assertEquals(editor.startOf(declaration), found.get(0).getRange().getStart());
    }

    /** The descriptor line a definition leads to. */
    private String descriptorLine(String program) throws IOException {
        editor.open(program);
        List<? extends Location> found = editor.definition();
        assertEquals(1, found.size(), found.toString());
        Path file = Path.of(URI.create(found.get(0).getUri()));
        return Files.readAllLines(file).get(found.get(0).getRange().getStart().getLine()).strip();
    }

    @Test
    void aBlockNameToItsEntry() {
        assertLeadsTo("inner (total", Programs.team("break(inn‸er);"));
        assertLeadsTo("work (.get", Programs.team("reelect(work‸);"));
        assertLeadsTo("work (.get", Programs.team("total = work.co‸unt;"));
        assertLeadsTo("work (.get", Programs.TEAM.replace("Entry work;", "Entry wo‸rk;"));
    }

    @Test
    void aVariableEventLabelOrAgentToItsDeclaration() {
        assertLeadsTo("total = 0", Programs.team("tot‸al++;"));
        assertLeadsTo("distance = 1.5", Programs.team("distance‸ = 2;"));
        assertLeadsTo("done;", Programs.team("emit(d‸one);"));
        assertLeadsTo("go;", Programs.team("emitWithMessage(g‸o, 1);"));
        assertLeadsTo("calls;", Programs.team("calls‸.r1.calibrate();"));
        assertLeadsTo("r1, r2", Programs.team("calls.r‸1.calibrate();"));
    }

    @Test
    void anAgentTypeToItsImport() {
        assertLeadsTo("Rover;", Programs.TEAM.replace("Rover r1", "Ro‸ver r1"));
        assertLeadsTo("Rover;", Programs.TEAM.replace("newAgent(Rover)", "newAgent(Rov‸er)"));
    }

    @Test
    void anImportToItsDescriptorsAgentElement() throws IOException {
        assertTrue(descriptorLine(Programs.TEAM.replace("SoftWheeledRobot.xml", "SoftWheeled‸Robot.xml"))
                .startsWith("<Agent short_class_name=\"SoftWheeledRobot\""));
        assertTrue(descriptorLine(Programs.TEAM.replace("as Rover", "as Rov‸er"))
                .startsWith("<Agent short_class_name=\"SoftWheeledRobot\""));
    }

    @Test
    void aPrimitiveOrAttributeToItsElementInTheDescriptorThatDeclaresIt() throws IOException {
        assertEquals("<Primitive function_name=\"logln\" member_id=\"D4\" synchronous_call=\"true\" return_type_name=\"void\">",
                descriptorLine(Programs.team(".logl‸n(\"x\");")));
        assertTrue(descriptorLine(Programs.team("r1.calibr‸ate();")).startsWith("<Primitive function_name=\"calibrate\""));
        assertTrue(descriptorLine(Programs.team("total = r1.MOVE_C‸OST;")).startsWith("<Attribute attribute_name=\"MOVE_COST\""));
    }

    @Test
    void aDescriptorNextToTheProgramIsOpenedWhereItIs() throws IOException {
        Path folder = Files.createTempDirectory("masl-lsp-definition");
        Path descriptor = folder.resolve("Rover.xml");
        try (var shipped = getClass().getResourceAsStream("/SoftWheeledRobot.xml")) {
            Files.copy(shipped, descriptor);
        }
        editor.open(folder.resolve("p.masl").toUri().toString(),
                Programs.TEAM.replace("SoftWheeledRobot.xml", "Rov‸er.xml"));
        List<? extends Location> found = editor.definition();
        assertEquals(descriptor.toUri().toString(), found.get(0).getUri());
    }
}
