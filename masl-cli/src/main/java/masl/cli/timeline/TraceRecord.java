package masl.cli.timeline;

import java.util.Map;

/**
 * One line of a JSON-lines trace as the timeline reads it: when, what, which agent (or -1 for a
 * mission-wide record such as a barrier trip), which block, and every other field as text.
 */
public record TraceRecord(int line, long nanos, String event, int agent, String block, Map<String, String> fields) {

    public static final int NO_AGENT = -1;

    public boolean hasAgent() {
        return agent != NO_AGENT;
    }

    public String field(String name) {
        return fields.get(name);
    }
}
