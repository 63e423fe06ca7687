package masl.runtime.entry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The agents a barrier holds: arrival order kept as a list keeps it, and a removal from anywhere
 * (a held agent that dies) costs O(1), not a scan of the held ones, so a wave whose members die
 * one by one while the others wait out costs linear, not quadratic, work. The work is counted, not
 * timed: the elements count the comparisons made of them.
 */
class HeldInOrderTest {

    private static final int HELD = 2_000;

    /** An element that counts how often it is compared for equality, with an id as its identity. */
    private static final class Counted {
        private final int id;
        private final int[] comparisons;

        Counted(int id, int[] comparisons) {
            this.id = id;
            this.comparisons = comparisons;
        }

        @Override
        public boolean equals(Object other) {
            comparisons[0]++;
            return other instanceof Counted counted && counted.id == id;
        }

        @Override
        public int hashCode() {
            return id;
        }

        @Override
        public String toString() {
            return "#" + id;
        }
    }

    @Test
    void removingHeldElementsFromAnywhereComparesEachWithOneElementAtMost() {
        int[] comparisons = new int[1];
        HeldInOrder<Counted> held = new HeldInOrder<>();
        for (int id = 0; id < HELD; id++) {
            held.add(new Counted(id, comparisons));
        }
        comparisons[0] = 0;
        // The latest arrivals leave first, and elements never held are removed too (a member that
        // dies while active): for a list, each a scan of what is held before it.
        for (int id = HELD - 1; id >= 0; id -= 2) {
            assertTrue(held.remove(new Counted(id, comparisons)));
            assertFalse(held.remove(new Counted(HELD + id, comparisons)));
        }
        assertTrue(comparisons[0] <= HELD, comparisons[0] + " comparisons for " + HELD + " removals");
        assertEquals(HELD / 2, held.size());
    }

    @Test
    void theHeldGoInArrivalOrderAndOneAddedAgainGoesLast() {
        HeldInOrder<String> held = new HeldInOrder<>();
        for (String agent : List.of("a", "b", "c", "d", "e")) {
            held.add(agent);
        }
        assertTrue(held.remove("c"));
        held.add("c");
        assertEquals(List.of("a", "b", "d", "e", "c"), held.toList());
        assertTrue(held.contains("d"));
        assertEquals("a", held.poll());
        List<String> iterated = new ArrayList<>();
        held.forEach(iterated::add);
        assertEquals(List.of("b", "d", "e", "c"), iterated);
        held.clear();
        assertTrue(held.isEmpty());
        assertNull(held.poll());
    }

    @Test
    void anElementIsHeldOnceAtMost() {
        HeldInOrder<String> held = new HeldInOrder<>();
        held.add("a");
        assertThrows(IllegalStateException.class, () -> held.add("a"));
        assertEquals(List.of("a"), held.toList());
    }
}
