package masl.runtime.descriptor;

import static masl.runtime.descriptor.TestDescriptors.assertSingleProblem;
import static masl.runtime.descriptor.TestDescriptors.problemsOf;
import static masl.runtime.descriptor.TestDescriptors.write;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A user's own {@code Default.xml} found first is the root type (components.md, "Agent path"), not a
 * subtype of the shipped one: its member ids and states are its own, and the types next to it that
 * name no supertype extend it. The fixture Default.xml on the agent path stands for the shipped one.
 */
class OwnRootTest {

    /** The root's five primitives with ids of its own, two more, and two more states. */
    private static final String OWN_DEFAULT = """
            <Agent short_class_name="Default" full_class_name="masl.runtime.descriptor.fixtures.Robot">
              <Primitive function_name="getProxyID" member_id="ID_1" synchronous_call="true"
                         return_type_name="int.class" accessor="true"/>
              <Primitive function_name="nop" member_id="ID_2" synchronous_call="true" return_type_name="void"/>
              <Primitive function_name="log" member_id="ID_3" synchronous_call="true" return_type_name="void">
                <Parameter parameter_name="message" parameter_type="java.lang.String"/>
              </Primitive>
              <Primitive function_name="logln" member_id="ID_4" synchronous_call="true" return_type_name="void">
                <Parameter parameter_name="message" parameter_type="java.lang.String"/>
              </Primitive>
              <Primitive function_name="sleep" member_id="ID_5" synchronous_call="true" return_type_name="void">
                <Parameter parameter_name="ms" parameter_type="long.class"/>
                <Exception exception_name="java.lang.InterruptedException"/>
              </Primitive>
              <Primitive function_name="move" member_id="ID_6" synchronous_call="false" return_type_name="void"
                         countermeasure="halt">
                <Parameter parameter_name="distance" parameter_type="double.class"/>
              </Primitive>
              <Primitive function_name="halt" member_id="ID_7" synchronous_call="false" return_type_name="void"/>
              <Permeability permeability_name="nothing" umask="777"/>
              <Permeability permeability_name="default" umask="000"/>
              <Permeability permeability_name="moving" umask="000">
                <Member member_id="ID_6" rights="111"/>
                <Member member_id="ID_7" rights="111"/>
              </Permeability>
              <Permeability permeability_name="parked" umask="000">
                <Member member_id="ID_4" rights="110"/>
                <Member member_id="ID_7" rights="100"/>
              </Permeability>
            </Agent>
            """;

    @TempDir
    Path folder;

    private Path ownDefault;

    @BeforeEach
    void writeOwnDefault() {
        ownDefault = write(folder, "Default.xml", OWN_DEFAULT);
    }

    @Test
    void itIsARootWithItsOwnIdsAndStates() {
        AgentType root = TestDescriptors.loader().load(ownDefault);
        assertNull(root.supertype());
        assertEquals(List.of("ID_1", "ID_2", "ID_3", "ID_4", "ID_5", "ID_6", "ID_7"),
                root.primitives().stream().map(Primitive::memberId).toList());
        assertEquals(List.of("nothing", "default", "moving", "parked"),
                root.states().stream().map(PermeabilityState::name).toList());
        PermeabilityState parked = root.findState("parked").orElseThrow();
        assertEquals(List.of(0110, 0100, 0), List.of(parked.rights("ID_4"), parked.rights("ID_7"), parked.rights("ID_6")));
    }

    @Test
    void theTypesNextToItExtendIt() {
        Path arm = write(folder, "Arm.xml", """
                <Agent short_class_name="Arm" full_class_name="masl.runtime.descriptor.fixtures.Khepera">
                  <Primitive function_name="instances" member_id="A1" synchronous_call="true" return_type_name="int">
                    <Modifier modifier_name="static"/>
                  </Primitive>
                  <Permeability permeability_name="parked" umask="000">
                    <Member member_id="A1" rights="111"/>
                  </Permeability>
                </Agent>
                """);
        DescriptorLoader loader = TestDescriptors.loader();
        AgentType type = loader.load(arm);
        assertSame(loader.load(ownDefault), type.supertype());
        assertEquals("masl.runtime.descriptor.fixtures.Robot", type.superFullClassName());
        PermeabilityState parked = type.findState("parked").orElseThrow();
        assertEquals(List.of(0111, 0110, 0100), List.of(parked.rights("A1"), parked.rights("ID_4"), parked.rights("ID_7")),
                "the redeclaration lists A1; the root's parked still gives ID_4 and ID_7");
    }

    @Test
    void theRootsIdsAreTheOnesItsSubtypesStatesName() {
        Path arm = write(folder, "Arm.xml", """
                <Agent short_class_name="Arm" full_class_name="masl.runtime.descriptor.fixtures.Khepera">
                  <Permeability permeability_name="quiet" umask="000">
                    <Member member_id="ID_4" rights="100"/>
                    <Member member_id="D4" rights="100"/>
                  </Permeability>
                </Agent>
                """);
        assertSingleProblem(problemsOf(() -> TestDescriptors.loader().load(arm)), arm, 4, 5,
                "<Member member_id=\"D4\">", "state 'quiet' names member_id 'D4', which is no member of Arm");
    }
}
