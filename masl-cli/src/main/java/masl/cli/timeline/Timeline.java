package masl.cli.timeline;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;

/**
 * What a trace says happened, laid out for drawing: the agents by their MASL names; per agent, the
 * spans of time it spent in its innermost block (running, or held at the block's entry or exit
 * barrier); barrier trips; the spans of each wave of each block; invocations from caller to callee;
 * events from their emitter to the agents that reacted; failures; and the other records of an
 * agent as markers.
 */
public final class Timeline {

    public enum State { RUNNING, WAITING_IN, WAITING_OUT }

    /** An agent in {@code block} (innermost), in {@code state}, from {@code start} to {@code end}. */
    public record Span(long start, long end, String block, State state) { }

    public record Trip(long nanos, String domain, String agents) { }

    public record WaveSpan(String block, String wave, long start, long end) { }

    /** How an invocation ended: the callee ran it, its permeability refused it, or the trace ends first. */
    public enum Outcome { SERVED, DENIED, PENDING }

    /**
     * {@code requester} (-1: from outside the mission) invoked {@code member} of {@code callee} at
     * {@code made}; at {@code resolved} the callee served it or its permeability state {@code state}
     * denied it.
     */
    public record Invocation(long made, long resolved, int requester, int callee, String member, Outcome outcome,
            String state, String source) { }

    public enum EventKind { EMITTED, REACTED, DROPPED }

    /**
     * A MASL event's record on an agent's lane. A reaction's {@code emission} is the index, in
     * {@link #events()}, of the latest emission of that event before it (-1 if none); {@code detail}
     * is an emission's message, a reaction's block.
     */
    public record EventMark(long nanos, int agent, String name, EventKind kind, String detail, int emission,
            String source) { }

    public record Failure(long nanos, int agent, String cause, String source) { }

    /**
     * Any other record of an agent: {@code kind} {@code first-entry} when it enters a nested block for
     * the first time, {@code left} when it leaves its outermost block, or the record's own kind
     * ({@code countermeasure-fired}).
     */
    public record Marker(long nanos, int agent, String kind, String label, String source) { }

    private final boolean inRecordOrder;
    private final long start;
    private final long end;
    private final Map<Integer, String> agents;
    private final Map<Integer, List<Span>> lanes;
    private final Set<String> blocks;
    private final List<Trip> trips;
    private final List<WaveSpan> waves;
    private final List<Invocation> invocations;
    private final List<EventMark> events;
    private final List<Failure> failures;
    private final List<Marker> markers;
    private final String status;

    private Timeline(TimelineBuilder built) {
        this.inRecordOrder = built.inRecordOrder;
        this.start = built.start;
        this.end = built.end;
        this.agents = built.agents;
        this.lanes = built.lanes;
        this.blocks = built.blocks;
        this.trips = built.trips;
        this.waves = built.waves;
        this.invocations = built.invocations;
        this.events = built.events;
        this.failures = built.failures;
        this.markers = built.markers;
        this.status = built.status;
    }

    /**
     * Lays out {@code records}. A trace whose records all bear one time (a seeded run that never
     * sleeps: its clock is virtual) is laid out in record order instead, one unit per record.
     */
    public static Timeline of(List<TraceRecord> records) {
        return new Timeline(new TimelineBuilder(records));
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

    /**
     * Every agent of the run by number, with its MASL name ({@code mission-started}), or
     * {@code agent N} for a trace that does not name it; in increasing number.
     */
    public Map<Integer, String> agents() {
        return agents;
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

    public List<Invocation> invocations() {
        return invocations;
    }

    public List<EventMark> events() {
        return events;
    }

    public List<Failure> failures() {
        return failures;
    }

    public List<Marker> markers() {
        return markers;
    }

    /**
     * How the mission ended ({@code mission-ended}), that the trace was cut at its limit before it
     * ended ({@code trace-cut}), or null if the trace does not say.
     */
    public String status() {
        return status;
    }

    /** Reads the records once, in order, into the timeline's parts. */
    private static final class TimelineBuilder {
        private final boolean inRecordOrder;
        private final long start;
        private final long end;
        private final Map<Integer, String> agents = new TreeMap<>();
        private final Map<Integer, List<Span>> lanes = new TreeMap<>();
        private final Set<String> blocks = new LinkedHashSet<>();
        private final List<Trip> trips = new ArrayList<>();
        private final List<WaveSpan> waves = new ArrayList<>();
        private final List<Invocation> invocations = new ArrayList<>();
        private final List<EventMark> events = new ArrayList<>();
        private final List<Failure> failures = new ArrayList<>();
        private final List<Marker> markers = new ArrayList<>();
        private String status;
        private final Map<Integer, AgentLane> agentLanes = new TreeMap<>();
        private final Map<String, Long> openWaves = new TreeMap<>();
        private final InvocationPairs pairs = new InvocationPairs();
        private final Map<String, Integer> lastEmission = new TreeMap<>();
        private final Set<String> firstEntries = new java.util.HashSet<>();

        TimelineBuilder(List<TraceRecord> records) {
            inRecordOrder = records.size() > 1 && records.stream().mapToLong(TraceRecord::nanos).distinct().count() == 1;
            if (inRecordOrder) {
                records = renumbered(records);
            }
            start = records.stream().mapToLong(TraceRecord::nanos).min().orElse(0);
            end = records.stream().mapToLong(TraceRecord::nanos).max().orElse(0);
            for (TraceRecord record : records) {
                read(record);
            }
            openWaves.forEach((key, opened) -> waves.add(new WaveSpan(key.substring(0, key.lastIndexOf('#')),
                    key.substring(key.lastIndexOf('#') + 1), opened, end)));
            invocations.addAll(pairs.pending());
            agentLanes.forEach((id, lane) -> lanes.put(id, lane.close(end)));
            agents.keySet().forEach(id -> lanes.putIfAbsent(id, List.of()));
            lanes.keySet().forEach(id -> agents.putIfAbsent(id, "agent " + id));
        }

        private static List<TraceRecord> renumbered(List<TraceRecord> records) {
            List<TraceRecord> ordered = new ArrayList<>();
            for (int i = 0; i < records.size(); i++) {
                TraceRecord r = records.get(i);
                ordered.add(new TraceRecord(r.line(), i, r.event(), r.agent(), r.block(), r.fields(), r.lists()));
            }
            return ordered;
        }

        private void read(TraceRecord record) {
            if (record.block() != null) {
                blocks.add(record.block());
            }
            String source = record.field("source");
            switch (record.event()) {
                case "mission-started" -> {
                    List<String> names = record.list("agents");
                    for (int id = 0; id < names.size(); id++) {
                        agents.put(id, names.get(id));
                    }
                }
                case "entered", "waiting-in", "released", "waiting-out", "left" -> membership(record, source);
                case "barrier-tripped" -> trips.add(new Trip(record.nanos(), record.field("domain"), record.field("agents")));
                case "wave-started" -> openWaves.put(record.block() + "#" + record.field("wave"), record.nanos());
                case "wave-ended" -> {
                    Long opened = openWaves.remove(record.block() + "#" + record.field("wave"));
                    waves.add(new WaveSpan(record.block(), record.field("wave"), opened == null ? start : opened, record.nanos()));
                }
                case "invocation-made" -> pairs.made(record);
                case "invocation-served" -> invocations.add(pairs.resolved(record, Outcome.SERVED));
                case "invocation-denied" -> invocations.add(pairs.resolved(record, Outcome.DENIED));
                case "event-emitted" -> {
                    lastEmission.put(record.field("name"), events.size());
                    events.add(new EventMark(record.nanos(), record.agent(), record.field("name"), EventKind.EMITTED,
                            record.field("message"), -1, source));
                }
                case "event-reacted" -> events.add(new EventMark(record.nanos(), record.agent(), record.field("name"),
                        EventKind.REACTED, record.block(), lastEmission.getOrDefault(record.field("name"), -1), source));
                case "event-dropped" -> events.add(new EventMark(record.nanos(), record.agent(), record.field("name"),
                        EventKind.DROPPED, null, -1, source));
                case "agent-failed" -> failures.add(new Failure(record.nanos(), record.agent(), record.field("cause"), source));
                case "mission-ended" -> status = record.field("status");
                case "trace-cut" -> status = "trace cut at its limit of " + record.field("limit") + " bytes";
                default -> {
                    if (record.hasAgent()) {
                        markers.add(new Marker(record.nanos(), record.agent(), record.event(), describe(record), source));
                    }
                }
            }
        }

        private void membership(TraceRecord record, String source) {
            AgentLane lane = agentLanes.computeIfAbsent(record.agent(), id -> new AgentLane(start));
            boolean nested = lane.depth() > 0;
            lane.apply(record);
            boolean entering = record.event().equals("entered") || record.event().equals("released");
            // Entering the outermost block is where the lane begins: only nested blocks are marked.
            if (entering && nested && firstEntries.add(record.agent() + ">" + record.block())) {
                markers.add(new Marker(record.nanos(), record.agent(), "first-entry", "enters " + record.block(), source));
            }
            if (record.event().equals("left") && lane.outside()) {
                markers.add(new Marker(record.nanos(), record.agent(), "left",
                        "left " + record.block() + " (" + record.field("cause") + ")", source));
            }
        }

        private static String describe(TraceRecord record) {
            StringBuilder label = new StringBuilder(record.event());
            record.fields().forEach((name, value) -> {
                if (!List.of("nanos", "event", "agent", "line", "source").contains(name)) {
                    label.append(' ').append(name).append('=').append(value);
                }
            });
            return label.toString();
        }
    }
}
