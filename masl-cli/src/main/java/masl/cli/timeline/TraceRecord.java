package masl.cli.timeline;

import java.util.List;
import java.util.Map;

/**
 * One line of a JSON-lines trace as the timeline reads it: when, what, which agent (or -1 for a
 * mission-wide record such as a barrier trip), which block (null for none), every other field as
 * text and every array field as a list of texts.
 */
public record TraceRecord(int line, long nanos, String event, int agent, String block, Map<String, String> fields,
        Map<String, List<String>> lists) {

    public static final int NO_AGENT = -1;

    public boolean hasAgent() {
        return agent != NO_AGENT;
    }

    public String field(String name) {
        return fields.get(name);
    }

    /** The array field {@code name}, empty when the record has none. */
    public List<String> list(String name) {
        return lists.getOrDefault(name, List.of());
    }
}
