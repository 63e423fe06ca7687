package masl.runtime.scheduling;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The draws of the seeded and lock-step schedulers: every task once, in an order the seed fixes. */
class SeededDrawTest {

    private static List<Integer> drawAll(long seed, int tasks) {
        SeededDraw draw = new SeededDraw(seed);
        List<Integer> order = new ArrayList<>();
        for (int i = 0; i < tasks; i++) {
            int task = i;
            draw.add(() -> order.add(task));
        }
        while (!draw.isEmpty()) {
            draw.draw().run();
        }
        return order;
    }

    @Test
    void everyTaskIsDrawnOnceInAnOrderTheSeedFixes() {
        assertEquals(drawAll(42, 6), drawAll(42, 6));
        assertEquals(List.of(0, 1, 2, 3, 4, 5), drawAll(42, 6).stream().sorted().toList());
    }

    /** A seed printed by a failed run ({@code masl run --seed N}) replays it with later versions too. */
    @Test
    void theOrderOfASeedStaysTheOneItWas() {
        assertEquals(List.of(2, 5, 4, 3, 1, 0), drawAll(42, 6));
        assertEquals(List.of(1, 4, 5, 3, 2, 0), drawAll(7, 6));
    }

    @Test
    void tasksAddedBetweenDrawsAreDrawnToo() {
        SeededDraw draw = new SeededDraw(1);
        List<String> ran = new ArrayList<>();
        draw.add(() -> ran.add("a"));
        draw.draw().run();
        assertTrue(draw.isEmpty());
        draw.add(() -> ran.add("b"));
        draw.add(() -> ran.add("c"));
        draw.draw().run();
        draw.draw().run();
        assertTrue(draw.isEmpty());
        assertEquals(List.of("a", "b", "c"), ran.stream().sorted().toList());
    }
}
