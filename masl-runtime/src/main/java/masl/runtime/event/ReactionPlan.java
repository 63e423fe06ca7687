package masl.runtime.event;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import masl.runtime.EntryDefinition;
import masl.runtime.Reaction;

/**
 * What one event processing does with the occurrences it took (MASL §8): each occurrence gets the
 * reaction found from the agent's innermost block outwards ({@code react(e)}, else
 * {@code react(default)}, then the parent); occurrences with none are dropped. The steps are
 * ordered by the block of their reaction, innermost first, then by the reaction's place among its
 * block's reactions, and occurrences of one reaction keep their order of perception.
 *
 * <p><b>Internal:</b> not part of the API; public only for the other packages of the runtime (Java has no
 * friend packages), and may change without notice.
 */
public final class ReactionPlan {

    /** One reaction to run, for one occurrence. */
    public record Step(EventOccurrence occurrence, Reaction reaction) { }

    private record Found(Step step, int level) { }

    private final List<Step> steps;
    private final List<EventOccurrence> dropped;

    private ReactionPlan(List<Step> steps, List<EventOccurrence> dropped) {
        this.steps = steps;
        this.dropped = dropped;
    }

    /**
     * Plans the processing of {@code perceived} (in order of perception) for an agent whose
     * blocks are {@code chain}, innermost first.
     */
    static ReactionPlan of(List<EventOccurrence> perceived, List<EntryDefinition> chain) {
        List<Found> found = new ArrayList<>();
        List<EventOccurrence> dropped = new ArrayList<>();
        for (EventOccurrence occurrence : perceived) {
            Found reaction = lookUp(occurrence, chain);
            if (reaction == null) {
                dropped.add(occurrence);
            } else {
                found.add(reaction);
            }
        }
        // List.sort is stable: occurrences of one reaction stay in order of perception.
        found.sort(Comparator.comparingInt(Found::level).thenComparingInt(f -> f.step().reaction().priority()));
        List<Step> steps = new ArrayList<>(found.size());
        found.forEach(f -> steps.add(f.step()));
        return new ReactionPlan(steps, dropped);
    }

    private static Found lookUp(EventOccurrence occurrence, List<EntryDefinition> chain) {
        for (int level = 0; level < chain.size(); level++) {
            Reaction reaction = chain.get(level).reactionTo(occurrence.event());
            if (reaction != null) {
                return new Found(new Step(occurrence, reaction), level);
            }
        }
        return null;
    }

    /** The reactions to run, in order. */
    List<Step> steps() {
        return steps;
    }

    /** The occurrences no block of the chain reacts to, in order of perception. */
    List<EventOccurrence> dropped() {
        return dropped;
    }
}
