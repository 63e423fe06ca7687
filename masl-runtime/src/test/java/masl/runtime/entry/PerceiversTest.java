package masl.runtime.entry;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Random;
import java.util.Set;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;

/** The receivers of a block's shared events: exact after each change, and lock-free readers see a published state. */
class PerceiversTest {

    private static final int CHANGES = 20_000;

    /** A scripted history of joins and leaves over 50 members; the states after each change. */
    private record Script(List<Integer> changes, Set<List<Integer>> states) { }

    private static Script script(long seed) {
        Random random = new Random(seed);
        LinkedHashSet<Integer> members = new LinkedHashSet<>();
        List<Integer> changes = new ArrayList<>();
        Set<List<Integer>> states = new HashSet<>();
        states.add(List.of());
        for (int i = 0; i < CHANGES; i++) {
            int member = random.nextInt(50);
            changes.add(member);
            if (!members.remove(member)) {
                members.add(member);
            }
            states.add(List.copyOf(members));
        }
        return new Script(changes, states);
    }

    /** Applies one scripted change: joins a non-member, removes a member. */
    private static void apply(Perceivers<Integer> perceivers, Set<Integer> members, int member) {
        if (members.remove(member)) {
            perceivers.remove(member);
        } else {
            members.add(member);
            perceivers.add(member);
        }
    }

    @Test
    void theSnapshotIsTheMembersInArrivalOrderAfterEveryChange() {
        Script script = script(7);
        Perceivers<Integer> perceivers = new Perceivers<>();
        LinkedHashSet<Integer> members = new LinkedHashSet<>();
        for (int member : script.changes()) {
            apply(perceivers, members, member);
            assertEquals(List.copyOf(members), List.of(perceivers.snapshot(Integer[]::new)));
        }
    }

    @Test
    void aLeaverAndAReturnerAreListedOnceInTheirNewArrivalOrder() {
        Perceivers<Integer> perceivers = new Perceivers<>();
        perceivers.add(1);
        perceivers.add(2);
        perceivers.add(2);
        perceivers.remove(1);
        perceivers.remove(3);
        perceivers.add(1);

        assertEquals(List.of(2, 1), List.of(perceivers.snapshot(Integer[]::new)));
    }

    /**
     * A reader taking snapshots without any lock while one writer changes the members sees only
     * states the members actually had after some change: a leave is never seen without the joins
     * that preceded it, nor a join without the leaves that preceded it.
     */
    @Test
    void aConcurrentReaderOnlySeesStatesTheMembersHad() throws InterruptedException {
        for (int round = 0; round < 20; round++) {
            Script script = script(round);
            Perceivers<Integer> perceivers = new Perceivers<>();
            AtomicBoolean done = new AtomicBoolean();
            AtomicReference<List<Integer>> impossible = new AtomicReference<>();
            CountDownLatch readerStarted = new CountDownLatch(1);
            Thread reader = new Thread(() -> {
                readerStarted.countDown();
                boolean last;
                do {
                    last = done.get();
                    List<Integer> seen = List.of(perceivers.snapshot(Integer[]::new));
                    if (!script.states().contains(seen)) {
                        impossible.compareAndSet(null, seen);
                    }
                } while (!last);
            });
            reader.start();
            readerStarted.await();
            Set<Integer> members = new HashSet<>();
            for (int member : script.changes()) {
                apply(perceivers, members, member);
            }
            done.set(true);
            reader.join();

            assertEquals(null, impossible.get(), "round " + round);
            assertTrue(script.states().contains(List.of(perceivers.snapshot(Integer[]::new))));
        }
    }
}
