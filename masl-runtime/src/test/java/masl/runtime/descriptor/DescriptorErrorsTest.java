package masl.runtime.descriptor;

import static masl.runtime.descriptor.TestDescriptors.agent;
import static masl.runtime.descriptor.TestDescriptors.assertProblem;
import static masl.runtime.descriptor.TestDescriptors.assertSingleProblem;
import static masl.runtime.descriptor.TestDescriptors.problemsOf;
import static masl.runtime.descriptor.TestDescriptors.write;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import masl.runtime.diagnostic.Diagnostic;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Each rule of agent-types.md ("Rules the loader enforces") broken once: the problem names the file,
 * the line and column of the element, and the element. Descriptors start with the XML declaration on
 * line 1 and {@code <Agent>} on line 2; members are on line 3 onwards, indented by 2 (column 3).
 */
class DescriptorErrorsTest {

    private static final String KHEPERA = "masl.runtime.descriptor.fixtures.Khepera";

    @TempDir
    Path folder;

    private List<Diagnostic> load(String xml) {
        Path file = write(folder, "T.xml", xml);
        return problemsOf(() -> TestDescriptors.loader().load(file));
    }

    private Path file() {
        return folder.resolve("T.xml");
    }

    private List<Diagnostic> loadKheperaWith(String body) {
        return load(agent(KHEPERA, body));
    }

    // --- XML and schema ---

    @Test
    void notWellFormed() {
        List<Diagnostic> problems = loadKheperaWith("""
                  <Class name="java.util.List">
                """);
        // Woodstox places the error inside the unexpected close tag.
        assertSingleProblem(problems, file(), 4, 7, "not well-formed XML", "</Agent>", "</Class>");
    }

    @Test
    void emptyFile() {
        assertSingleProblem(load(""), file(), 1, 1, "not well-formed XML", "Unexpected EOF");
    }

    @Test
    void missingFile() {
        Path absent = folder.resolve("Absent.xml");
        Diagnostic problem = problemsOf(() -> TestDescriptors.loader().load(absent)).get(0);
        assertEquals(absent.toString(), problem.file());
        assertEquals(0, problem.line());
        assertEquals(absent + ": error: file not found", problem.toString());
    }

    @Test
    void elementInANamespaceIsNotADescriptorElement() {
        List<Diagnostic> problems = load("""
                <?xml version="1.0"?>
                <m:Agent xmlns:m="urn:masl" short_class_name="T" full_class_name="masl.runtime.descriptor.fixtures.Robot"/>
                """);
        assertSingleProblem(problems, file(), 2, 1, "the root element must be <Agent>, not <m:Agent>");
    }

    @Test
    void problemPrintsAsFileLineColumn() {
        assertEquals("a/T.xml:3:5: error: boom", Diagnostic.error("a/T.xml", 3, 5, "boom").toString());
        assertEquals("a/T.xml:3: error: boom", Diagnostic.error("a/T.xml", 3, 0, "boom").toString());
        assertEquals("a/T.xml: error: boom", Diagnostic.error("a/T.xml", 0, 0, "boom").toString());
    }

    @Test
    void unknownAttribute() {
        List<Diagnostic> problems = loadKheperaWith("""
                  <Attribute attribute_name="battery" member_id="A1" attribute_class="int" colour="red"/>
                """);
        assertSingleProblem(problems, file(), 3, 3, "<Attribute>: unknown attribute 'colour'");
    }

    @Test
    void missingAttribute() {
        List<Diagnostic> problems = loadKheperaWith("""
                  <Primitive function_name="stopGripper" synchronous_call="false" return_type_name="void"/>
                """);
        assertSingleProblem(problems, file(), 3, 3, "<Primitive>: missing attribute 'member_id'");
    }

    @ParameterizedTest
    @CsvSource({"en", "de", "fr", "ja", "es"})
    void schemaMessagesAreRephrasedWhateverTheDefaultLanguage(String language) {
        Locale before = Locale.getDefault();
        Locale.setDefault(Locale.forLanguageTag(language));
        try {
            List<Diagnostic> problems = loadKheperaWith("""
                      <Attribute attribute_name="battery" member_id="A1" attribute_class="int" colour="red"/>
                      <Permeability permeability_name="open" umask="8"/>
                      <Sensor/>
                    """);
            assertEquals(3, problems.size(), () -> TestDescriptors.render(problems));
            assertProblem(problems.get(0), file(), 3, 3, "<Attribute>: unknown attribute 'colour'");
            assertProblem(problems.get(1), file(), 4, 3, "<Permeability>: invalid value '8' for attribute 'umask':"
                    + " expected 3 octal digits");
            assertProblem(problems.get(2), file(), 5, 3, "unknown or misplaced element <Sensor>: expected <Class>");
        } finally {
            Locale.setDefault(before);
        }
    }

    @Test
    void missingAttributeOfAgent() {
        List<Diagnostic> problems = load("""
                <?xml version="1.0"?>
                <Agent full_class_name="masl.runtime.descriptor.fixtures.Khepera"/>
                """);
        assertSingleProblem(problems, file(), 2, 1, "<Agent>: missing attribute 'short_class_name'");
    }

    @Test
    void unknownElement() {
        List<Diagnostic> problems = loadKheperaWith("""
                  <Attribute attribute_name="battery" member_id="A1" attribute_class="int"/>
                  <Sensor name="sonar"/>
                """);
        assertSingleProblem(problems, file(), 4, 3, "unknown or misplaced element <Sensor>",
                "expected <Class>, <Attribute>, <Primitive>, <Permeability>");
    }

    @Test
    void rootElementMustBeAgent() {
        List<Diagnostic> problems = load("""
                <?xml version="1.0"?>
                <Robot short_class_name="T"/>
                """);
        assertSingleProblem(problems, file(), 2, 1, "the root element must be <Agent>, not <Robot>");
    }

    @Test
    void textIsNotAllowed() {
        List<Diagnostic> problems = loadKheperaWith("""
                  hello
                """);
        assertEquals(1, problems.size(), () -> TestDescriptors.render(problems));
        assertEquals("<Agent>: text is not allowed here, only elements", problems.get(0).message());
    }

    @ParameterizedTest
    @CsvSource({"88", "1111", "64", "rw-"})
    void rightsMustBeThreeOctalDigits(String rights) {
        List<Diagnostic> problems = loadKheperaWith("""
                  <Permeability permeability_name="open" umask="000">
                    <Member member_id="D1" rights="%s"/>
                  </Permeability>
                """.formatted(rights));
        assertSingleProblem(problems, file(), 4, 5,
                "<Member>: invalid value '" + rights + "' for attribute 'rights': expected 3 octal digits");
    }

    @Test
    void umaskMustBeThreeOctalDigits() {
        List<Diagnostic> problems = loadKheperaWith("""
                  <Permeability permeability_name="open" umask="9"/>
                """);
        assertSingleProblem(problems, file(), 3, 3,
                "<Permeability>: invalid value '9' for attribute 'umask': expected 3 octal digits");
    }

    @Test
    void booleanAttributeMustBeTrueOrFalse() {
        List<Diagnostic> problems = loadKheperaWith("""
                  <Primitive function_name="stopGripper" member_id="P3" synchronous_call="yes"
                             return_type_name="void"/>
                """);
        assertSingleProblem(problems, file(), 3, 3,
                "invalid value 'yes' for attribute 'synchronous_call': expected true or false");
    }

    @Test
    void unknownModifier() {
        List<Diagnostic> problems = loadKheperaWith("""
                  <Attribute attribute_name="battery" member_id="A1" attribute_class="int">
                    <Modifier modifier_name="volatile"/>
                  </Attribute>
                """);
        assertSingleProblem(problems, file(), 4, 5, "<Modifier>: invalid value 'volatile'",
                "expected public, static or final");
    }

    // --- members and states of one file ---

    @Test
    void duplicateMemberId() {
        List<Diagnostic> problems = loadKheperaWith("""
                  <Attribute attribute_name="battery" member_id="A1" attribute_class="int"/>
                  <Primitive function_name="stopGripper" member_id="A1" synchronous_call="false" return_type_name="void"/>
                """);
        assertSingleProblem(problems, file(), 4, 3, "<Primitive function_name=\"stopGripper\">",
                "duplicate member_id 'A1'", "<Attribute attribute_name=\"battery\"> on line 3");
    }

    @Test
    void duplicateMemberName() {
        List<Diagnostic> problems = loadKheperaWith("""
                  <Primitive function_name="stopGripper" member_id="P3" synchronous_call="false" return_type_name="void"/>
                  <Attribute attribute_name="stopGripper" member_id="A9" attribute_class="int"/>
                """);
        assertSingleProblem(problems, file(), 4, 3, "<Attribute attribute_name=\"stopGripper\">",
                "duplicate member name 'stopGripper'", "line 3");
    }

    @Test
    void duplicateStateName() {
        List<Diagnostic> problems = loadKheperaWith("""
                  <Permeability permeability_name="open" umask="000"/>
                  <Permeability permeability_name="open" umask="777"/>
                """);
        assertSingleProblem(problems, file(), 4, 3, "<Permeability permeability_name=\"open\">",
                "state 'open' is already declared on line 3");
    }

    @Test
    void memberListedTwiceInAState() {
        List<Diagnostic> problems = loadKheperaWith("""
                  <Permeability permeability_name="open" umask="000">
                    <Member member_id="D1" rights="111"/>
                    <Member member_id="D1" rights="100"/>
                  </Permeability>
                """);
        assertSingleProblem(problems, file(), 5, 5, "<Member member_id=\"D1\">", "already listed in state 'open'");
    }

    @Test
    void memberNamingAnUnknownId() {
        List<Diagnostic> problems = loadKheperaWith("""
                  <Permeability permeability_name="open" umask="000">
                    <Member member_id="D1" rights="111"/>
                    <Member member_id="P9" rights="111"/>
                  </Permeability>
                """);
        assertSingleProblem(problems, file(), 5, 5, "<Member member_id=\"P9\">",
                "state 'open' names member_id 'P9', which is no member of T");
    }

    @Test
    void countermeasureNamingNoPrimitive() {
        List<Diagnostic> problems = loadKheperaWith("""
                  <Primitive function_name="startGripper" member_id="P2" synchronous_call="false"
                             return_type_name="void" countermeasure="dropGripper"/>
                """);
        assertSingleProblem(problems, file(), 3, 3, "<Primitive function_name=\"startGripper\">",
                "countermeasure 'dropGripper' names no primitive of T");
    }

    @Test
    void countermeasureNamingItself() {
        List<Diagnostic> problems = loadKheperaWith("""
                  <Primitive function_name="startGripper" member_id="P2" synchronous_call="false"
                             return_type_name="void" countermeasure="startGripper"/>
                """);
        assertSingleProblem(problems, file(), 3, 3, "countermeasure 'startGripper' names the primitive itself");
    }

    @Test
    void countermeasureOnASynchronousPrimitive() {
        List<Diagnostic> problems = loadKheperaWith("""
                  <Primitive function_name="startGripper" member_id="P2" synchronous_call="true"
                             return_type_name="void" countermeasure="nop"/>
                """);
        assertSingleProblem(problems, file(), 3, 3, "countermeasure 'nop' on a synchronous primitive");
    }

    @Test
    void countermeasureTakingParameters() {
        List<Diagnostic> problems = loadKheperaWith("""
                  <Primitive function_name="startGripper" member_id="P2" synchronous_call="false"
                             return_type_name="void" countermeasure="log"/>
                """);
        assertSingleProblem(problems, file(), 3, 3, "countermeasure 'log' takes parameters");
    }

    @Test
    void everyProblemOfAFileIsReportedInFileOrder() {
        List<Diagnostic> problems = loadKheperaWith("""
                  <Attribute attribute_name="battery" member_id="A1" attribute_class="int" colour="red"/>
                  <Primitive function_name="fly" member_id="P8" synchronous_call="true" return_type_name="void"/>
                  <Permeability permeability_name="open" umask="000">
                    <Member member_id="P9" rights="111"/>
                    <Member member_id="P1" rights="9"/>
                  </Permeability>
                """);
        assertEquals(4, problems.size(), () -> TestDescriptors.render(problems));
        assertProblem(problems.get(0), file(), 3, 3, "unknown attribute 'colour'");
        assertProblem(problems.get(1), file(), 4, 3, "has no public method void fly()");
        assertProblem(problems.get(2), file(), 6, 5, "member_id 'P9'");
        assertProblem(problems.get(3), file(), 7, 5, "invalid value '9' for attribute 'rights'");
    }
}
