package masl.runtime.descriptor;

import static masl.runtime.descriptor.TestDescriptors.agent;
import static masl.runtime.descriptor.TestDescriptors.assertSingleProblem;
import static masl.runtime.descriptor.TestDescriptors.problemsOf;
import static masl.runtime.descriptor.TestDescriptors.write;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import java.util.List;
import masl.runtime.diagnostic.Diagnostic;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The descriptor against its Java implementation class (fixtures.Khepera unless said otherwise). */
class ImplementationErrorsTest {

    private static final String FIXTURES = "masl.runtime.descriptor.fixtures.";

    @TempDir
    Path folder;

    private Path file;

    private List<Diagnostic> load(String className, String body) {
        file = write(folder, "T.xml", agent(className, body));
        return problemsOf(() -> TestDescriptors.loader().load(file));
    }

    private List<Diagnostic> loadKheperaWith(String body) {
        return load(FIXTURES + "Khepera", body);
    }

    @Test
    void implementationClassMissing() {
        assertSingleProblem(load(FIXTURES + "Missing", ""), file, 2, 1,
                "implementation class 'masl.runtime.descriptor.fixtures.Missing' not found");
    }

    @Test
    void implementationClassWithoutNoArgumentConstructor() {
        assertSingleProblem(load(FIXTURES + "NoDefaultConstructor", ""), file, 2, 1,
                "has no public no-argument constructor");
    }

    @Test
    void implementationClassMustExtendTheSupertypesClass() {
        assertSingleProblem(load(FIXTURES + "Vector2d", ""), file, 2, 1,
                "'masl.runtime.descriptor.fixtures.Vector2d' does not extend 'masl.runtime.descriptor.fixtures.Default'");
    }

    @Test
    void methodMissing() {
        assertSingleProblem(loadKheperaWith("""
                  <Primitive function_name="fly" member_id="P8" synchronous_call="true" return_type_name="void">
                    <Parameter parameter_name="height" parameter_type="int.class"/>
                  </Primitive>
                """), file, 3, 3, "<Primitive function_name=\"fly\">",
                "'masl.runtime.descriptor.fixtures.Khepera' has no public method void fly(int)");
    }

    @Test
    void methodWithOtherParameterTypes() {
        assertSingleProblem(loadKheperaWith("""
                  <Primitive function_name="getProximity" member_id="P1" synchronous_call="true" return_type_name="int">
                    <Parameter parameter_name="sensor" parameter_type="double.class"/>
                  </Primitive>
                """), file, 3, 3, "has no public method int getProximity(double)");
    }

    @Test
    void methodWithOtherReturnType() {
        assertSingleProblem(loadKheperaWith("""
                  <Primitive function_name="getProximity" member_id="P1" synchronous_call="true" return_type_name="long">
                    <Parameter parameter_name="sensor" parameter_type="int"/>
                  </Primitive>
                """), file, 3, 3, "method getProximity of 'masl.runtime.descriptor.fixtures.Khepera' returns int,"
                + " the descriptor says long");
    }

    @Test
    void staticMethodNotDeclaredStatic() {
        assertSingleProblem(loadKheperaWith("""
                  <Primitive function_name="instances" member_id="P4" synchronous_call="true" return_type_name="int"/>
                """), file, 3, 3, "method instances", "is static, the descriptor does not say static");
    }

    @Test
    void instanceMethodDeclaredStatic() {
        assertSingleProblem(loadKheperaWith("""
                  <Primitive function_name="stopGripper" member_id="P3" synchronous_call="false" return_type_name="void">
                    <Modifier modifier_name="static"/>
                  </Primitive>
                """), file, 3, 3, "method stopGripper", "is not static, the descriptor says static");
    }

    @Test
    void unknownParameterType() {
        assertSingleProblem(loadKheperaWith("""
                  <Primitive function_name="stopGripper" member_id="P3" synchronous_call="false" return_type_name="void">
                    <Parameter parameter_name="how" parameter_type="org.example.Grip"/>
                  </Primitive>
                """), file, 3, 3, "type 'org.example.Grip' of parameter 'how' not found");
    }

    @Test
    void exceptionThatIsNoThrowable() {
        assertSingleProblem(loadKheperaWith("""
                  <Primitive function_name="stopGripper" member_id="P3" synchronous_call="false" return_type_name="void">
                    <Exception exception_name="java.lang.String"/>
                  </Primitive>
                """), file, 3, 3, "exception 'java.lang.String' is not a Throwable");
    }

    @Test
    void fieldMissing() {
        assertSingleProblem(loadKheperaWith("""
                  <Attribute attribute_name="speed" member_id="A5" attribute_class="double.class"/>
                """), file, 3, 3, "<Attribute attribute_name=\"speed\">", "has no public field double speed");
    }

    @Test
    void fieldOfAnotherType() {
        assertSingleProblem(loadKheperaWith("""
                  <Attribute attribute_name="battery" member_id="A1" attribute_class="java.lang.String"/>
                """), file, 3, 3, "field battery", "has type int, the descriptor says java.lang.String");
    }

    @Test
    void staticFieldNotDeclaredStatic() {
        assertSingleProblem(loadKheperaWith("""
                  <Attribute attribute_name="count" member_id="A3" attribute_class="int"/>
                """), file, 3, 3, "field count", "is static, the descriptor does not say static");
    }

    @Test
    void finalMismatch() {
        assertSingleProblem(loadKheperaWith("""
                  <Attribute attribute_name="battery" member_id="A1" attribute_class="int">
                    <Modifier modifier_name="final"/>
                  </Attribute>
                """), file, 3, 3, "field battery", "is not final, the descriptor says final");
    }

    @Test
    void utilityClassMissing() {
        assertSingleProblem(loadKheperaWith("""
                  <Class name="org.example.Matrix"/>
                """), file, 3, 3, "<Class name=\"org.example.Matrix\">", "utility class 'org.example.Matrix' not found");
    }

    /**
     * A mission from the cache reads the descriptors its translation checked, with the classes it
     * checked them against (the cache's key covers both): they are not checked again
     * ({@link DescriptorLoader#readingValidated}): that reflection was 15 ms of a 0.25 s run from the cache.
     */
    @Test
    void descriptorsReadAsValidatedBeforeAreNotCheckedAgainstTheirClassesAgain() {
        file = write(folder, "T.xml", agent(FIXTURES + "Khepera", """
                  <Primitive function_name="fly" member_id="P8" synchronous_call="true" return_type_name="void">
                    <Parameter parameter_name="height" parameter_type="int.class"/>
                  </Primitive>
                """));
        AgentType type = DescriptorLoader.readingValidated(() -> TestDescriptors.loader().load(file));
        assertEquals(FIXTURES + "Khepera", type.fullClassName());
    }
}
