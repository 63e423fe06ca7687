package masl.cli.timeline;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import masl.cli.timeline.Timeline.Span;
import masl.cli.timeline.Timeline.State;

/** One agent's chain of blocks and state as its membership records arrive, closed into spans. */
final class AgentLane {
    private final Deque<String> chain = new ArrayDeque<>();
    private final List<Span> spans = new ArrayList<>();
    private State state = State.RUNNING;
    private String waitingAt;
    private long since;

    AgentLane(long start) {
        this.since = start;
    }

    void apply(TraceRecord record) {
        close(record.nanos(), record.event().equals("left") ? record.block() : null);
        switch (record.event()) {
            case "entered" -> {
                chain.push(record.block());
                state = State.RUNNING;
            }
            case "waiting-in" -> {
                state = State.WAITING_IN;
                waitingAt = record.block();
            }
            case "released" -> {
                // A synchronous block's members are released into it, with no "entered" record.
                if (!record.block().equals(chain.peek())) {
                    chain.push(record.block());
                }
                state = State.RUNNING;
            }
            case "waiting-out" -> {
                state = State.WAITING_OUT;
                waitingAt = record.block();
            }
            default -> {
                chain.remove(record.block());
                state = State.RUNNING;
            }
        }
        since = record.nanos();
    }

    /** How many blocks the agent is a member of (held at an entry barrier is not yet a member). */
    int depth() {
        return chain.size();
    }

    /** Whether the agent is in no block: it left its outermost one. */
    boolean outside() {
        return chain.isEmpty() && state == State.RUNNING;
    }

    List<Span> close(long end) {
        String block = state == State.RUNNING ? chain.peek() : waitingAt;
        close(end, block);
        return spans;
    }

    /**
     * Ends the current span at {@code at}. A span of no time is kept when its block is the one
     * being left ({@code leaving}): on a simulated clock an agent may enter and leave a block
     * within one physics step, and the page draws that a few pixels wide.
     */
    private void close(long at, String leaving) {
        String block = state == State.RUNNING ? chain.peek() : waitingAt;
        if (block != null && (at > since || block.equals(leaving))) {
            spans.add(new Span(since, Math.max(at, since), block, state));
        }
    }
}
