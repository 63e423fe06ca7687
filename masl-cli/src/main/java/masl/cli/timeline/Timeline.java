package masl.cli.timeline;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;

/**
 * What a trace says happened, laid out for drawing: per agent, the spans of time it spent in its
 * innermost block (running, or held at the block's entry or exit barrier); barrier trips; the
 * spans of each wave of each block; and every other record of an agent (events, invocations) as a
 * marker at its time.
 */
public final class Timeline {

    public enum State { RUNNING, WAITING_IN, WAITING_OUT }

    /** An agent in {@code block} (innermost), in {@code state}, from {@code start} to {@code end}. */
    public record Span(long start, long end, String block, State state) { }

    public record Trip(long nanos, String domain, String agents) { }

    public record WaveSpan(String block, String wave, long start, long end) { }

    public record Marker(long nanos, int agent, String label) { }

    private final boolean inRecordOrder;
    private final long start;
    private final long end;
    private final Map<Integer, List<Span>> lanes;
    private final Set<String> blocks;
    private final List<Trip> trips;
    private final List<WaveSpan> waves;
    private final List<Marker> markers;

    private Timeline(boolean inRecordOrder, long start, long end, Map<Integer, List<Span>> lanes, Set<String> blocks, List<Trip> trips,
            List<WaveSpan> waves, List<Marker> markers) {
        this.inRecordOrder = inRecordOrder;
        this.start = start;
        this.end = end;
        this.lanes = lanes;
        this.blocks = blocks;
        this.trips = trips;
        this.waves = waves;
        this.markers = markers;
    }

    /**
     * Lays out {@code records}. A trace whose records all bear one time (a seeded run that never
     * sleeps: its clock is virtual) is laid out in record order instead, one unit per record.
     */
    public static Timeline of(List<TraceRecord> records) {
        boolean inRecordOrder = records.size() > 1 && records.stream().mapToLong(TraceRecord::nanos).distinct().count() == 1;
        if (inRecordOrder) {
            List<TraceRecord> ordered = new ArrayList<>();
            for (int i = 0; i < records.size(); i++) {
                TraceRecord record = records.get(i);
                ordered.add(new TraceRecord(record.line(), i, record.event(), record.agent(), record.block(), record.fields()));
            }
            records = ordered;
        }
        long start = records.stream().mapToLong(TraceRecord::nanos).min().orElse(0);
        long end = records.stream().mapToLong(TraceRecord::nanos).max().orElse(0);
        Map<Integer, AgentLane> agents = new TreeMap<>();
        Set<String> blocks = new LinkedHashSet<>();
        List<Trip> trips = new ArrayList<>();
        List<WaveSpan> waves = new ArrayList<>();
        Map<String, Long> openWaves = new TreeMap<>();
        List<Marker> markers = new ArrayList<>();
        for (TraceRecord record : records) {
            if (record.block() != null) {
                blocks.add(record.block());
            }
            switch (record.event()) {
                case "entered", "waiting-in", "released", "waiting-out", "left" ->
                        agents.computeIfAbsent(record.agent(), id -> new AgentLane(start)).apply(record);
                case "barrier-tripped" -> trips.add(new Trip(record.nanos(), record.field("domain"), record.field("agents")));
                case "wave-started" -> openWaves.put(record.block() + "#" + record.field("wave"), record.nanos());
                case "wave-ended" -> {
                    Long opened = openWaves.remove(record.block() + "#" + record.field("wave"));
                    waves.add(new WaveSpan(record.block(), record.field("wave"), opened == null ? start : opened, record.nanos()));
                }
                default -> {
                    if (record.hasAgent()) {
                        markers.add(new Marker(record.nanos(), record.agent(), describe(record)));
                    }
                }
            }
        }
        openWaves.forEach((key, opened) -> waves.add(new WaveSpan(key.substring(0, key.lastIndexOf('#')),
                key.substring(key.lastIndexOf('#') + 1), opened, end)));
        Map<Integer, List<Span>> lanes = new TreeMap<>();
        agents.forEach((id, lane) -> lanes.put(id, lane.close(end)));
        return new Timeline(inRecordOrder, start, end, lanes, blocks, trips, waves, markers);
    }

    private static String describe(TraceRecord record) {
        StringBuilder label = new StringBuilder(record.event());
        record.fields().forEach((name, value) -> {
            if (!name.equals("nanos") && !name.equals("event") && !name.equals("agent")) {
                label.append(' ').append(name).append('=').append(value);
            }
        });
        return label.toString();
    }

    /** Whether times are record numbers rather than nanoseconds (see {@link #of}). */
    public boolean inRecordOrder() {
        return inRecordOrder;
    }

    public long start() {
        return start;
    }

    public long end() {
        return end;
    }

    /** Agent number to its spans, in time order; agents in increasing number. */
    public Map<Integer, List<Span>> lanes() {
        return lanes;
    }

    /** Every block named in the trace, in order of first appearance. */
    public Set<String> blocks() {
        return blocks;
    }

    public List<Trip> trips() {
        return trips;
    }

    public List<WaveSpan> waves() {
        return waves;
    }

    public List<Marker> markers() {
        return markers;
    }

    /** One agent's chain of blocks and state as its records arrive. */
    private static final class AgentLane {
        private final Deque<String> chain = new ArrayDeque<>();
        private final List<Span> spans = new ArrayList<>();
        private State state = State.RUNNING;
        private String waitingAt;
        private long since;

        AgentLane(long start) {
            this.since = start;
        }

        void apply(TraceRecord record) {
            close(record.nanos(), false);
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

        List<Span> close(long end) {
            close(end, true);
            return spans;
        }

        private void close(long at, boolean last) {
            String block = state == State.RUNNING ? chain.peek() : waitingAt;
            if (block != null && (at > since || last)) {
                spans.add(new Span(since, Math.max(at, since), block, state));
            }
        }
    }
}
