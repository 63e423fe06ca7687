package masl.jade.deployment;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.List;
import masl.runtime.AgentImplementation;
import masl.runtime.AgentServices;
import masl.runtime.testing.TestAgent;
import org.junit.jupiter.api.Test;

/**
 * Values as they travel between a mission and its containers, through JSON text as over JADE: arrays
 * of every MASL element type come back as arrays of that type, tagged with MASL's names, never a
 * Java class's.
 */
class ValuesTest {

    private static final ObjectMapper MAPPER = new ObjectMapper();

    /** The agents of the receiving side, by proxy id: scouts, a rover's subtype, and a rover. */
    private final List<AgentImplementation> agents = List.of(agent(new Scout(), 0), agent(new Scout(), 1),
            agent(new Rover(), 2));

    @Test
    void arraysOfPrimitivesComeBackOfTheirType() throws Exception {
        assertArrayEquals(new int[] {1, -2, Integer.MAX_VALUE}, (int[]) travel(new int[] {1, -2, Integer.MAX_VALUE}));
        assertArrayEquals(new long[] {Long.MIN_VALUE, 7}, (long[]) travel(new long[] {Long.MIN_VALUE, 7}));
        assertArrayEquals(new short[] {-3, 300}, (short[]) travel(new short[] {-3, 300}));
        assertArrayEquals(new byte[] {-128, 127}, (byte[]) travel(new byte[] {-128, 127}));
        assertArrayEquals(new boolean[] {true, false}, (boolean[]) travel(new boolean[] {true, false}));
        assertArrayEquals(new char[] {'a', '"', '\u00e9'}, (char[]) travel(new char[] {'a', '"', '\u00e9'}));
        assertArrayEquals(new float[] {0.1f, Float.NaN, Float.NEGATIVE_INFINITY},
                (float[]) travel(new float[] {0.1f, Float.NaN, Float.NEGATIVE_INFINITY}));
        assertArrayEquals(new double[] {0.1, Double.NaN, Double.POSITIVE_INFINITY, -0.0, Double.MIN_VALUE},
                (double[]) travel(new double[] {0.1, Double.NaN, Double.POSITIVE_INFINITY, -0.0, Double.MIN_VALUE}));
        assertEquals(0, ((int[]) travel(new int[0])).length);
    }

    @Test
    void arraysOfStringsKeepTheirNulls() throws Exception {
        assertArrayEquals(new String[] {"rover 2: 1 laps", null, ""}, (String[]) travel(new String[] {"rover 2: 1 laps", null, ""}));
        assertArrayEquals(new String[3], (String[]) travel(new String[3]));
    }

    @Test
    void nestedArraysKeepTheirShapeAndTheirNullRows() throws Exception {
        int[][] grid = {{1, 2}, null, {}, {3}};
        int[][] back = (int[][]) travel(grid);
        assertEquals(4, back.length);
        assertArrayEquals(grid[0], back[0]);
        assertNull(back[1]);
        assertArrayEquals(grid[3], back[3]);
        String[][][] cube = {{{"a"}, null}, null};
        assertEquals("a", ((String[][][]) travel(cube))[0][0][0]);
    }

    @Test
    void anArrayOfAgentsTakesTheAgentTypeTheReceiverExpects() throws Exception {
        Rover[] sent = {agent(new Scout(), 1), null, agent(new Rover(), 2)};
        Object back = Values.fromJson(wire(sent), agents, Values.NONE, Rover[].class);
        assertSame(Rover[].class, back.getClass());
        Rover[] rovers = (Rover[]) back;
        assertSame(agents.get(1), rovers[0]);
        assertNull(rovers[1]);
        assertSame(agents.get(2), rovers[2]);
        Rover[][] teams = (Rover[][]) Values.fromJson(wire(new Rover[][] {{}, sent}), agents, Values.NONE, Rover[][].class);
        assertSame(agents.get(2), teams[1][2]);
        // No agents of that type at all, and no type expected: an array of agents.
        assertEquals(AgentImplementation[].class, Values.fromJson(wire(new Scout[0]), agents, Values.NONE).getClass());
    }

    @Test
    void theWireNamesMaslTypesNeverAJavaClass() throws Exception {
        Rover[][] team = {{agent(new Rover(), 2)}};
        assertEquals("{\"agent[][]\":[[2]]}", MAPPER.writeValueAsString(Values.toJson(team)));
        assertEquals("{\"string[]\":[\"a\",null]}", MAPPER.writeValueAsString(Values.toJson(new String[] {"a", null})));
        for (Object array : List.of(new int[1][1], new char[] {'x'}, new double[] {1.5})) {
            String wire = MAPPER.writeValueAsString(Values.toJson(array));
            assertFalse(wire.contains("java") || wire.contains("[I") || wire.contains("[C"), wire);
        }
    }

    @Test
    void anArrayOfOtherElementsDoesNotTravelAndSaysWhichItIs() {
        IllegalArgumentException objects = assertThrows(IllegalArgumentException.class,
                () -> Values.toJson(new Object[] {"a"}));
        assertTrue(objects.getMessage().contains("Object[] value cannot travel"), objects.getMessage());
        assertThrows(IllegalArgumentException.class, () -> Values.toJson(new Integer[] {1}));
    }

    @Test
    void anArrayOfAnotherTypeThanTheReceiverExpectsIsRefused() throws Exception {
        JsonNode strings = wire(new String[] {"a"});
        assertThrows(IllegalArgumentException.class, () -> Values.fromJson(strings, agents, Values.NONE, int[].class));
        assertThrows(IllegalArgumentException.class, () -> Values.fromJson(strings, agents, Values.NONE, String[][].class));
        assertThrows(IllegalArgumentException.class, () -> Values.fromJson(wire(new int[0]), agents, Values.NONE, long[].class));
        assertThrows(IllegalArgumentException.class,
                () -> Values.fromJson(MAPPER.readTree("{\"object[]\":[]}"), agents, Values.NONE));
    }

    @Test
    void numbersJsonHasNoNumberForTravelToo() throws Exception {
        assertEquals(Double.NaN, travel(Double.NaN));
        assertEquals(Double.NEGATIVE_INFINITY, travel(Double.NEGATIVE_INFINITY));
        assertEquals(Float.POSITIVE_INFINITY, travel(Float.POSITIVE_INFINITY));
        assertEquals(0.25, travel(0.25));
    }

    private Object travel(Object value) throws Exception {
        return Values.fromJson(wire(value), agents, Values.NONE);
    }

    private static JsonNode wire(Object value) throws Exception {
        return MAPPER.readTree(MAPPER.writeValueAsString(Values.toJson(value)));
    }

    private static <A extends AgentImplementation> A agent(A agent, int proxyId) {
        agent.bind(new AgentServices() {
            @Override
            public int proxyId() {
                return proxyId;
            }

            @Override
            public void log(String text) {
            }

            @Override
            public void sleep(long ms) {
            }
        });
        return agent;
    }

    /** An agent type of the program. */
    public static class Rover extends TestAgent {
    }

    /** A subtype of {@link Rover}. */
    public static class Scout extends Rover {
    }
}
