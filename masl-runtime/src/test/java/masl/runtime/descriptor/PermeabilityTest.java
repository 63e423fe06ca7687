package masl.runtime.descriptor;

import static masl.runtime.descriptor.TestDescriptors.agent;
import static masl.runtime.descriptor.TestDescriptors.write;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import masl.runtime.descriptor.PermeabilityState.Requester;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The states of a type, inheritance applied (README, "Descriptors"). */
class PermeabilityTest {

    private AgentType khepera;

    @BeforeEach
    void loadKhepera() {
        khepera = TestDescriptors.loader().load(TestDescriptors.fixtureFolder().resolve("Khepera.xml"));
    }

    @Test
    void statesAreInheritedInOrderRedeclaredInPlaceThenOwn() {
        assertEquals(List.of("nothing", "default", "busy", "careful"),
                khepera.states().stream().map(PermeabilityState::name).toList());
        assertEquals("default", khepera.initialState().orElseThrow().name());
        assertEquals(37, khepera.findState("default").orElseThrow().line(), "Khepera's redeclaration");
    }

    @Test
    void listedMembersGetTheirRightsMaskedByTheUmask() {
        PermeabilityState defaultState = khepera.findState("default").orElseThrow();
        assertEquals(0, defaultState.umask());
        assertEquals(0111, defaultState.rights("P1"));
        assertEquals(0644, defaultState.rights("A1"));
        PermeabilityState careful = khepera.findState("careful").orElseThrow();
        assertEquals(0002, careful.umask());
        assertEquals(0664, careful.rights("A1"), "666 & ~002");
        assertEquals(0, careful.rights("P1"), "a state that lists members gives the others none");
    }

    @Test
    void unlistedMembersInheritFromTheRedeclaredAllowAllDefault() {
        PermeabilityState defaultState = khepera.findState("default").orElseThrow();
        assertEquals(0777, defaultState.rights("P2"), "new in Khepera, not listed: the root's default allows all");
        assertEquals(0777, defaultState.rights("D3"), "inherited from the root");
        assertEquals(0777, defaultState.rights("R1"), "inherited from Robot");
        assertEquals(0, defaultState.rights("nonsense"), "not a member");
    }

    @Test
    void anInheritedStateKeepsItsRightsAndGivesNewMembersNone() {
        PermeabilityState busy = khepera.findState("busy").orElseThrow();
        assertEquals(0110, busy.rights("R1"));
        assertEquals(0, busy.rights("P1"), "new in Khepera");
        assertEquals(0, busy.rights("D1"), "Robot's busy does not list the root's members");
        assertEquals(0, khepera.findState("nothing").orElseThrow().rights("P1"), "umask 777 denies everything");
    }

    @Test
    void requesterDigits() {
        PermeabilityState defaultState = khepera.findState("default").orElseThrow();
        assertTrue(defaultState.allows("A1", Requester.SELF, PermeabilityState.WRITE));
        assertTrue(defaultState.allows("A1", Requester.OTHER, PermeabilityState.READ));
        assertFalse(defaultState.allows("A1", Requester.GROUP, PermeabilityState.WRITE));
        assertTrue(defaultState.allows("P1", Requester.OTHER, PermeabilityState.INVOKE));
        PermeabilityState busy = khepera.findState("busy").orElseThrow();
        assertTrue(busy.allows("R1", Requester.GROUP, PermeabilityState.INVOKE));
        assertFalse(busy.allows("R1", Requester.OTHER, PermeabilityState.INVOKE));
    }

    @Test
    void aRedeclaredStateWithoutMembersAllowsEverything(@TempDir Path folder) {
        Path file = write(folder, "Open.xml", """
                <Agent short_class_name="Open" full_class_name="masl.runtime.descriptor.fixtures.Khepera"
                       super_full_class_name="masl.runtime.descriptor.fixtures.Robot">
                  <Permeability permeability_name="busy" umask="000"/>
                </Agent>
                """);
        AgentType open = TestDescriptors.loader().load(file);
        assertEquals(0777, open.findState("busy").orElseThrow().rights("D1"));
        assertEquals(0777, open.findState("busy").orElseThrow().rights("R1"));
    }

    /** {@code unlisted_rights}: "everything but" a state can say without listing every member of every subtype. */
    @Test
    void unlistedRightsGoToEveryMemberAStateDoesNotList(@TempDir Path folder) {
        Path robot = write(folder, "Robot.xml", """
                <Agent short_class_name="Robot" full_class_name="masl.runtime.descriptor.fixtures.Robot">
                  <Attribute attribute_name="name" member_id="R3" attribute_class="java.lang.String"/>
                  <Primitive function_name="move" member_id="R1" synchronous_call="false" return_type_name="void"
                             countermeasure="halt">
                    <Parameter parameter_name="distance" parameter_type="double.class"/>
                  </Primitive>
                  <Primitive function_name="halt" member_id="R2" synchronous_call="false" return_type_name="void"/>
                  <Permeability permeability_name="busy" umask="000" unlisted_rights="775">
                    <Member member_id="R1" rights="110"/>
                  </Permeability>
                </Agent>
                """);
        Path sub = write(folder, "Sub.xml", """
                <Agent short_class_name="Sub" full_class_name="masl.runtime.descriptor.fixtures.Khepera"
                       super_full_class_name="masl.runtime.descriptor.fixtures.Robot">
                  <Primitive function_name="getProximity" member_id="P1" synchronous_call="true"
                             return_type_name="int.class" accessor="true">
                    <Parameter parameter_name="sensor" parameter_type="int.class"/>
                  </Primitive>
                  <Permeability permeability_name="busy" umask="000">
                    <Member member_id="R2" rights="700"/>
                  </Permeability>
                </Agent>
                """);
        DescriptorLoader loader = TestDescriptors.loader(folder);
        AgentType allButMove = loader.load(robot);
        PermeabilityState busy = allButMove.findState("busy").orElseThrow();
        assertEquals(0110, busy.rights("R1"), "listed");
        assertEquals(0775, busy.rights("R2"), "not listed");
        assertEquals(0775, busy.rights("D1"), "not listed, inherited");
        assertEquals(0, allButMove.findState("nothing").orElseThrow().rights("D1"), "other states as they were");
        PermeabilityState subBusy = loader.load(sub).findState("busy").orElseThrow();
        assertEquals(0110, subBusy.rights("R1"), "listed higher up");
        assertEquals(0700, subBusy.rights("R2"), "listed here");
        assertEquals(0775, subBusy.rights("P1"), "new in the subtype: the unlisted rights of the state it redeclares");
    }

    @Test
    void aRootWithoutStatesHasNoInitialStateSoEverythingIsAllowed(@TempDir Path folder) {
        Path file = write(folder, "Bare.xml", agent("masl.runtime.descriptor.fixtures.Vector2d", ""));
        AgentType bare = new DescriptorLoader(AgentPath.of(List.of(), getClass().getClassLoader()), null).load(file);
        assertTrue(bare.states().isEmpty());
        assertTrue(bare.initialState().isEmpty());
    }

    @Test
    void withoutDefaultTheInitialStateIsTheFirst(@TempDir Path folder) {
        Path file = write(folder, "Two.xml", agent("masl.runtime.descriptor.fixtures.Vector2d", """
                  <Permeability permeability_name="closed" umask="777"/>
                  <Permeability permeability_name="open" umask="000"/>
                """));
        AgentType two = new DescriptorLoader(AgentPath.of(List.of(), getClass().getClassLoader()), null).load(file);
        assertEquals("closed", two.initialState().orElseThrow().name());
    }

    /**
     * Robot's {@code chatty} state names the root's {@code log} as D3; Scribe redefines {@code log} as
     * S1 and names S1 in a state of its own. Each state's ids are its own descriptor's.
     */
    @Test
    void aRedefinitionWithItsOwnIdKeepsTheInheritedStatesRightsAndIsNamedByItsOwnStates(@TempDir Path folder) {
        write(folder, "Robot.xml", """
                <Agent short_class_name="Robot" full_class_name="masl.runtime.descriptor.fixtures.Robot">
                  <Permeability permeability_name="chatty" umask="000">
                    <Member member_id="D3" rights="111"/>
                    <Member member_id="D4" rights="100"/>
                  </Permeability>
                </Agent>
                """);
        Path file = write(folder, "Scribe.xml", """
                <Agent short_class_name="Scribe" full_class_name="masl.runtime.descriptor.fixtures.Khepera"
                       super_full_class_name="masl.runtime.descriptor.fixtures.Robot">
                  <Primitive function_name="log" member_id="S1" synchronous_call="true" return_type_name="void">
                    <Parameter parameter_name="message" parameter_type="java.lang.String"/>
                  </Primitive>
                  <Permeability permeability_name="hushed" umask="000">
                    <Member member_id="S1" rights="100"/>
                    <Member member_id="D4" rights="110"/>
                  </Permeability>
                </Agent>
                """);
        AgentType scribe = TestDescriptors.loader().load(file);
        assertEquals("S1", scribe.findPrimitive("log").orElseThrow().memberId());
        PermeabilityState chatty = scribe.findState("chatty").orElseThrow();
        assertEquals(List.of(0111, 0100, 0), List.of(chatty.rights("S1"), chatty.rights("D4"), chatty.rights("D3")),
                "Robot's rights for its D3 are the redefined log's, now S1; D3 names nothing in Scribe");
        PermeabilityState hushed = scribe.findState("hushed").orElseThrow();
        assertEquals(List.of(0100, 0110, 0), List.of(hushed.rights("S1"), hushed.rights("D4"), hushed.rights("D1")));
        assertEquals(0777, scribe.findState("default").orElseThrow().rights("S1"), "the root's default allows all");
        assertEquals(0, scribe.findState("nothing").orElseThrow().rights("S1"));
    }
}
