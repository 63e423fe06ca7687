package masl.cli.timeline;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import masl.cli.timeline.Timeline.Invocation;
import masl.cli.timeline.Timeline.Outcome;

/**
 * Pairs each {@code invocation-made} with the {@code invocation-served} or {@code -denied} that
 * ends it (same requester, callee and member, first made first ended), so that an invocation is one
 * arrow from the caller when it asked to the callee when it answered.
 */
final class InvocationPairs {

    private final Map<String, Deque<TraceRecord>> made = new LinkedHashMap<>();

    void made(TraceRecord record) {
        made.computeIfAbsent(key(record), k -> new ArrayDeque<>()).add(record);
    }

    /** The invocation {@code record} ends; one made at the same time if the trace has no such {@code made}. */
    Invocation resolved(TraceRecord record, Outcome outcome) {
        Deque<TraceRecord> waiting = made.get(key(record));
        TraceRecord asked = waiting == null || waiting.isEmpty() ? record : waiting.poll();
        return new Invocation(asked.nanos(), record.nanos(), number(record, "requester"), number(record, "callee"),
                record.field("member"), outcome, record.field("state"), asked.field("source"));
    }

    /** The invocations made and never served nor denied. */
    List<Invocation> pending() {
        List<Invocation> left = new ArrayList<>();
        made.values().forEach(queue -> queue.forEach(asked -> left.add(new Invocation(asked.nanos(), asked.nanos(),
                number(asked, "requester"), number(asked, "callee"), asked.field("member"), Outcome.PENDING, null,
                asked.field("source")))));
        return left;
    }

    private static String key(TraceRecord record) {
        return record.field("requester") + ">" + record.field("callee") + "." + record.field("member");
    }

    private static int number(TraceRecord record, String field) {
        try {
            return Integer.parseInt(record.field(field));
        } catch (NumberFormatException | NullPointerException notANumber) {
            return TraceRecord.NO_AGENT;
        }
    }
}
