package masl.runtime.event;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;
import masl.runtime.EntryDefinition;
import masl.runtime.Event;
import masl.runtime.Mode;
import masl.runtime.Reaction;
import org.junit.jupiter.api.Test;

/** Reactions as declared (MASL §8) and the plan of one event processing: lookup, order, dropping. */
class ReactionLookupTest {

    // main { event a, b, c, d; react(b); react(default);
    //   mid { react(c);
    //     inner { react(d); react(a); } } }
    private final EntryDefinition main = EntryDefinition.main("main", Mode.ASYNCHRONOUS);
    private final Event a = main.declareLocalEvent("a");
    private final Event b = main.declareSharedEvent("b");
    private final Event c = main.declareLocalEvent("c");
    private final Event d = main.declareLocalEvent("d");
    private final EntryDefinition mid = main.child("mid", Mode.SYNCHRONOUS);
    private final EntryDefinition inner = mid.child("inner", Mode.ASYNCHRONOUS);
    private final Reaction mainB = main.react(b);
    private final Reaction mainDefault = main.reactToDefault();
    private final Reaction midC = mid.react(c);
    private final Reaction innerD = inner.react(d);
    private final Reaction innerA = inner.react(a);
    private final List<EntryDefinition> chain = List.of(inner, mid, main);

    @Test
    void aBlocksReactionToTheEventComesBeforeItsDefaultWhateverTheOrderWritten() {
        EntryDefinition block = EntryDefinition.main("x", Mode.ASYNCHRONOUS);
        Event e = block.declareLocalEvent("e");
        Reaction fallback = block.reactToDefault();
        Reaction toE = block.react(e);
        assertSame(toE, block.reactionTo(e));
        assertSame(fallback, block.reactionTo(Event.TIMEOUT));
        assertNull(inner.reactionTo(b));
        assertEquals(List.of(fallback, toE), block.reactions());
        assertEquals(1, toE.priority());
    }

    @Test
    void occurrencesAreOrderedByBlockInnermostFirstThenByReactionThenByPerception() {
        List<EventOccurrence> perceived = List.of(occurrence(b, "b1"), occurrence(a, "a1"), occurrence(c, "c1"),
                occurrence(d, "d1"), occurrence(a, "a2"), occurrence(Event.TIMEOUT, "t"), occurrence(b, "b2"));
        ReactionPlan plan = ReactionPlan.of(perceived, chain);
        assertEquals(List.of("d1:" + innerD, "a1:" + innerA, "a2:" + innerA, "c1:" + midC,
                "b1:" + mainB, "b2:" + mainB, "t:" + mainDefault), describe(plan));
        assertEquals(List.of(), plan.dropped());
    }

    @Test
    void theLookupStartsAtTheInnermostBlockOfTheAgentNow() {
        // The same occurrences for an agent that is in mid only: inner's reactions are out of reach.
        ReactionPlan plan = ReactionPlan.of(List.of(occurrence(a, "a"), occurrence(d, "d"), occurrence(c, "c")),
                List.of(mid, main));
        assertEquals(List.of("c:" + midC, "a:" + mainDefault, "d:" + mainDefault), describe(plan));
    }

    @Test
    void occurrencesWithoutAnyReactionInTheChainAreDropped() {
        EntryDefinition other = EntryDefinition.main("other", Mode.ASYNCHRONOUS);
        EntryDefinition child = other.child("child", Mode.ASYNCHRONOUS);
        Event e = other.declareLocalEvent("e");
        Event f = other.declareLocalEvent("f");
        Reaction childF = child.react(f);
        EventOccurrence lost = occurrence(e, "lost");
        ReactionPlan plan = ReactionPlan.of(List.of(lost, occurrence(f, "f")), List.of(child, other));
        assertEquals(List.of("f:" + childF), describe(plan));
        assertEquals(List.of(lost), plan.dropped());
    }

    @Test
    void aReactionMustNameAnEventVisibleInItsBlockAndOnlyOnce() {
        Event ofInner = inner.declareSharedEvent("local_to_inner");
        assertThrows(IllegalArgumentException.class, () -> mid.react(ofInner));
        assertThrows(IllegalArgumentException.class, () -> inner.react(a));
        assertThrows(IllegalArgumentException.class, () -> main.reactToDefault());
        assertThrows(IllegalArgumentException.class, () -> main.declareLocalEvent("a"));
        assertSame(inner, inner.react(ofInner).block());
        assertSame(Event.FORBIDDEN_ACCESS, mid.react(Event.FORBIDDEN_ACCESS).event());
    }

    private static EventOccurrence occurrence(Event event, String message) {
        return new EventOccurrence(event, message, 0);
    }

    private static List<String> describe(ReactionPlan plan) {
        return plan.steps().stream().map(step -> step.occurrence().message() + ":" + step.reaction()).toList();
    }
}
