package masl.runtime.descriptor;

import static masl.runtime.descriptor.TestDescriptors.assertProblem;
import static masl.runtime.descriptor.TestDescriptors.assertSingleProblem;
import static masl.runtime.descriptor.TestDescriptors.problemsOf;
import static masl.runtime.descriptor.TestDescriptors.write;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;
import masl.runtime.diagnostic.Diagnostic;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Supertype resolution and the rules that involve inherited members. */
class InheritanceErrorsTest {

    @TempDir
    Path folder;

    /** A Khepera-class descriptor extending the fixture Robot, with {@code body}; members from line 4. */
    private Path kheperaUnderRobot(String body) {
        return write(folder, "Sub.xml", """
                <?xml version="1.0"?>
                <Agent short_class_name="Sub" full_class_name="masl.runtime.descriptor.fixtures.Khepera"
                       super_full_class_name="masl.runtime.descriptor.fixtures.Robot">
                """ + body + "</Agent>\n");
    }

    @Test
    void supertypeNotFound() {
        Path file = write(folder, "Lost.xml", """
                <?xml version="1.0"?>
                <Agent short_class_name="Lost" full_class_name="masl.runtime.descriptor.fixtures.Khepera"
                       super_full_class_name="org.example.Nowhere"/>
                """);
        assertSingleProblem(problemsOf(() -> TestDescriptors.loader().load(file)), file, 2, 1,
                "<Agent full_class_name=\"masl.runtime.descriptor.fixtures.Khepera\">",
                "supertype 'org.example.Nowhere' not found");
    }

    @Test
    void implicitRootNotFound() {
        Path file = write(folder, "Alone.xml", """
                <?xml version="1.0"?>
                <Agent short_class_name="Alone" full_class_name="masl.runtime.descriptor.fixtures.Vector2d"/>
                """);
        DescriptorLoader loader = new DescriptorLoader(AgentPath.of(List.of(), getClass().getClassLoader()));
        assertSingleProblem(problemsOf(() -> loader.load(file)), file, 2, 1,
                "implicit supertype 'masl.agents.Default' not found");
    }

    @Test
    void cycleInSupertypes() {
        Path robot = write(folder, "Robot.xml", """
                <?xml version="1.0"?>
                <Agent short_class_name="R" full_class_name="masl.runtime.descriptor.fixtures.Robot"
                       super_full_class_name="masl.runtime.descriptor.fixtures.Khepera"/>
                """);
        Path khepera = write(folder, "Khepera.xml", """
                <?xml version="1.0"?>

                <Agent short_class_name="K" full_class_name="masl.runtime.descriptor.fixtures.Khepera"
                       super_full_class_name="masl.runtime.descriptor.fixtures.Robot"/>
                """);
        List<Diagnostic> problems = problemsOf(() -> TestDescriptors.loader().load(robot));
        assertEquals(2, problems.size(), () -> TestDescriptors.render(problems));
        assertProblem(problems.get(0), robot, 2, 1, "supertype 'masl.runtime.descriptor.fixtures.Khepera'",
                "has errors");
        assertProblem(problems.get(1), khepera, 3, 1, "cycle in supertypes: masl.runtime.descriptor.fixtures.Robot"
                + " -> masl.runtime.descriptor.fixtures.Khepera -> masl.runtime.descriptor.fixtures.Robot");
    }

    @Test
    void typeNamingItselfAsSupertype() {
        Path file = write(folder, "Self.xml", """
                <?xml version="1.0"?>
                <Agent short_class_name="Self" full_class_name="masl.runtime.descriptor.fixtures.Khepera"
                       super_full_class_name="masl.runtime.descriptor.fixtures.Khepera"/>
                """);
        assertSingleProblem(problemsOf(() -> TestDescriptors.loader().load(file)), file, 2, 1,
                "cycle in supertypes: masl.runtime.descriptor.fixtures.Khepera -> masl.runtime.descriptor.fixtures.Khepera");
    }

    @Test
    void problemsOfTheSupertypeComeAfterThoseOfTheSubtype() {
        Path broken = write(folder, "Robot.xml", """
                <?xml version="1.0"?>
                <Agent short_class_name="Robot" full_class_name="masl.runtime.descriptor.fixtures.Robot">
                  <Primitive function_name="halt" member_id="R2" synchronous_call="maybe" return_type_name="void"/>
                </Agent>
                """);
        Path file = kheperaUnderRobot("");
        List<Diagnostic> problems = problemsOf(() -> TestDescriptors.loader().load(file));
        assertEquals(2, problems.size(), () -> TestDescriptors.render(problems));
        assertProblem(problems.get(0), file, 2, 1, "supertype 'masl.runtime.descriptor.fixtures.Robot' (" + broken
                + ") has errors");
        assertProblem(problems.get(1), broken, 3, 3, "invalid value 'maybe'");
    }

    @Test
    void aRedefinitionMayTakeAnIdOfItsOwn() {
        Path file = kheperaUnderRobot("""
                  <Primitive function_name="halt" member_id="K9" synchronous_call="true" return_type_name="void"/>
                """);
        AgentType sub = TestDescriptors.loader().load(file);
        assertEquals(List.of("D1", "D2", "D3", "D4", "D5", "R1", "K9"),
                sub.primitives().stream().map(Primitive::memberId).toList(), "halt redefined in place, as K9");
    }

    @Test
    void aRedefinitionMustNotTakeTheIdOfAnotherInheritedMember() {
        Path file = kheperaUnderRobot("""
                  <Primitive function_name="halt" member_id="R1" synchronous_call="true" return_type_name="void"/>
                """);
        assertSingleProblem(problemsOf(() -> TestDescriptors.loader().load(file)), file, 4, 3,
                "<Primitive function_name=\"halt\">", "duplicate member_id 'R1': already used by 'move' of Robot");
    }

    @Test
    void aStateNamesTheRedefinitionsOwnIdNotTheOneItReplaced() {
        Path file = kheperaUnderRobot("""
                  <Primitive function_name="halt" member_id="K9" synchronous_call="true" return_type_name="void"/>
                  <Permeability permeability_name="calm" umask="000">
                    <Member member_id="K9" rights="100"/>
                    <Member member_id="R2" rights="100"/>
                  </Permeability>
                """);
        assertSingleProblem(problemsOf(() -> TestDescriptors.loader().load(file)), file, 7, 5,
                "<Member member_id=\"R2\">", "state 'calm' names member_id 'R2', which is no member of Sub",
                "it is the id of 'halt' in Robot", "which Sub redefines as 'K9'");
    }

    @Test
    void newMemberMustNotTakeAnInheritedId() {
        Path file = kheperaUnderRobot("""
                  <Primitive function_name="stopGripper" member_id="R1" synchronous_call="false" return_type_name="void"/>
                """);
        assertSingleProblem(problemsOf(() -> TestDescriptors.loader().load(file)), file, 4, 3,
                "duplicate member_id 'R1': already used by 'move' of Robot");
    }

    @Test
    void newMemberMustNotTakeAnIdOfTheRoot() {
        Path file = kheperaUnderRobot("""
                  <Attribute attribute_name="battery" member_id="D1" attribute_class="int"/>
                """);
        assertSingleProblem(problemsOf(() -> TestDescriptors.loader().load(file)), file, 4, 3,
                "duplicate member_id 'D1': already used by 'getProxyID' of Default");
    }

    @Test
    void attributeMustNotTakeTheNameOfAnInheritedPrimitive() {
        Path file = kheperaUnderRobot("""
                  <Attribute attribute_name="move" member_id="R1" attribute_class="int"/>
                """);
        List<Diagnostic> problems = problemsOf(() -> TestDescriptors.loader().load(file));
        assertEquals(2, problems.size(), () -> TestDescriptors.render(problems));
        assertProblem(problems.get(0), file, 4, 3, "attribute 'move' has the name of a primitive inherited from Robot");
        assertProblem(problems.get(1), file, 4, 3, "has no public field int move");
    }

    @Test
    void stateMayNameInheritedMembersButNotUnknownOnes() {
        Path file = kheperaUnderRobot("""
                  <Permeability permeability_name="busy" umask="000">
                    <Member member_id="D1" rights="100"/>
                    <Member member_id="R1" rights="100"/>
                    <Member member_id="K1" rights="100"/>
                  </Permeability>
                """);
        assertSingleProblem(problemsOf(() -> TestDescriptors.loader().load(file)), file, 7, 5,
                "<Member member_id=\"K1\">", "no member of Sub");
    }

    @Test
    void countermeasureMayNameAnInheritedPrimitive() {
        Path file = kheperaUnderRobot("""
                  <Primitive function_name="startGripper" member_id="P2" synchronous_call="false"
                             return_type_name="void" countermeasure="halt"/>
                """);
        assertEquals("halt", TestDescriptors.loader().load(file).findPrimitive("startGripper").orElseThrow()
                .countermeasure());
    }
}
