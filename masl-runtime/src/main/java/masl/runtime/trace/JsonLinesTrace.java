package masl.runtime.trace;

import java.io.Flushable;
import java.io.IOException;
import java.util.Optional;
import java.util.function.Consumer;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Writes one JSON object per line for every event (components.md, "Runtime"), in the order they
 * happened, for {@code --trace FILE}: for instance
 * {@code {"nanos":123,"event":"left","agent":2,"block":"work","cause":"reelect"}}. Names are
 * written as JSON strings, escaped; a MASL event's own name goes under {@code "name"}, as in
 * {@code {"nanos":124,"event":"event-reacted","agent":1,"name":"go","block":"main","reaction":"go"}}.
 * A record made where an agent's program stands at a statement ends with that statement's MASL line
 * and source, when the program knows them: {@code ,"line":14,"source":"e6.masl:14: synchronous entry turn (…)"}.
 *
 * <p>A trace has a limit in bytes (UTF-8): the record that would take it past its limit is not
 * written, a last record {@code {"nanos":N,"event":"trace-cut","limit":BYTES}} is, within the limit,
 * and nothing after it. A write that fails loses the trace: nothing more is written, and the
 * action of {@link #whenFailed} runs once (the mission is stopped, never an agent's thread failed).
 */
public final class JsonLinesTrace implements Trace, Flushable {

    /** The line in a source {@code "file.masl:14: …"}: the number after the file's name. */
    private static final Pattern POSITION = Pattern.compile("[^:]*:(\\d+):");

    /** The event of the last record of a trace cut at its limit. */
    public static final String CUT = "trace-cut";
    /** Room kept for the record saying the trace was cut: the longest, a 19-digit time and limit, fits. */
    private static final int CUT_RECORD_ROOM = 96;
    /** The limit of a trace unless one is given: 1 GiB, more than one means to read or draw. */
    public static final long DEFAULT_LIMIT = 1L << 30;
    /** The smallest limit: the first records of a mission and the cut record fit. */
    public static final long MIN_LIMIT = 1024;

    private final Appendable out;
    private final long limit;
    private long written;
    /** {@code mission-ended} or the cut record was written: it stays the last line, whatever agents still finishing record. */
    private boolean ended;
    private boolean cut;
    private IOException failure;
    private Consumer<IOException> onFailure = failed -> { };

    /** A trace without limit. */
    public JsonLinesTrace(Appendable out) {
        this(out, Long.MAX_VALUE);
    }

    /** A trace cut at {@code limit} bytes, at least {@link #MIN_LIMIT}. */
    public JsonLinesTrace(Appendable out, long limit) {
        if (limit < MIN_LIMIT) {
            throw new IllegalArgumentException("a trace's limit is at least " + MIN_LIMIT + " bytes: " + limit);
        }
        this.out = out;
        this.limit = limit;
    }

    /** What to do on the first write that fails (at once if one has): the trace is lost. */
    public void whenFailed(Consumer<IOException> action) {
        IOException failed;
        synchronized (this) {
            onFailure = action;
            failed = failure;
        }
        if (failed != null) {
            action.accept(failed);
        }
    }

    /** The write that failed, if one has. */
    public synchronized Optional<IOException> failure() {
        return Optional.ofNullable(failure);
    }

    /** Whether the trace reached its limit and ends with the record saying so. */
    public synchronized boolean wasCut() {
        return cut;
    }

    @Override
    public void record(TraceEvent event) {
        IOException failed;
        Consumer<IOException> action;
        synchronized (this) {
            if (ended || failure != null) {
                return;
            }
            try {
                write(event);
                return;
            } catch (IOException e) {
                failure = e;
                failed = e;
                action = onFailure;
            }
        }
        action.accept(failed);
    }

    private void write(TraceEvent event) throws IOException {
        String line;
        if (event instanceof TraceEvent.MissionStarted e) {
            line = head(e.nanos(), "mission-started") + ",\"agents\":["
                    + String.join(",", e.agents().stream().map(JsonLinesTrace::string).toList()) + "]";
        } else if (event instanceof TraceEvent.MissionEnded e) {
            ended = true;
            line = head(e.nanos(), "mission-ended") + ",\"status\":" + string(e.status())
                    + (e.reason() == null ? "" : ",\"reason\":" + string(e.reason()));
        } else if (event instanceof TraceEvent.AgentFailed e) {
            line = head(e.nanos(), "agent-failed") + ",\"agent\":" + e.agent() + ",\"cause\":" + string(e.cause());
        } else if (event instanceof TraceEvent.Entered e) {
            line = membership(e.nanos(), "entered", e.agent(), e.block());
        } else if (event instanceof TraceEvent.WaitingIn e) {
            line = membership(e.nanos(), "waiting-in", e.agent(), e.block());
        } else if (event instanceof TraceEvent.Released e) {
            line = membership(e.nanos(), "released", e.agent(), e.block()) + ",\"wave\":" + e.wave();
        } else if (event instanceof TraceEvent.WaitingOut e) {
            line = membership(e.nanos(), "waiting-out", e.agent(), e.block());
        } else if (event instanceof TraceEvent.Left e) {
            line = membership(e.nanos(), "left", e.agent(), e.block())
                    + ",\"cause\":" + string(e.cause().name().toLowerCase());
        } else if (event instanceof TraceEvent.BarrierTripped e) {
            line = head(e.nanos(), "barrier-tripped") + ",\"domain\":" + string(e.domain()) + ",\"agents\":" + e.agents();
        } else if (event instanceof TraceEvent.WaveStarted e) {
            line = head(e.nanos(), "wave-started") + ",\"block\":" + string(e.block()) + ",\"wave\":" + e.wave();
        } else if (event instanceof TraceEvent.WaveEnded e) {
            line = head(e.nanos(), "wave-ended") + ",\"block\":" + string(e.block()) + ",\"wave\":" + e.wave();
        } else {
            line = eventLine(event);
        }
        String record = line + source(event.source()) + "}\n";
        long bytes = utf8Length(record);
        if (written + bytes > limit - CUT_RECORD_ROOM && !(event instanceof TraceEvent.MissionEnded && written + bytes <= limit)) {
            ended = true;
            cut = true;
            out.append(head(event.nanos(), CUT) + ",\"limit\":" + limit + "}\n");
            return;
        }
        written += bytes;
        out.append(record);
    }

    /** The length of {@code text} in UTF-8, without encoding it. */
    private static long utf8Length(String text) {
        long bytes = 0;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (c < 0x80) {
                bytes++;
            } else if (c < 0x800) {
                bytes += 2;
            } else if (Character.isHighSurrogate(c) && i + 1 < text.length() && Character.isLowSurrogate(text.charAt(i + 1))) {
                bytes += 4;
                i++;
            } else {
                bytes += 3;
            }
        }
        return bytes;
    }

    @Override
    public synchronized void flush() throws IOException {
        if (out instanceof Flushable flushable) {
            flushable.flush();
        }
    }

    /** The lines of MASL events; their name is written under {@code "name"}, {@code "event"} being the kind. */
    private static String eventLine(TraceEvent event) {
        if (event instanceof TraceEvent.EventEmitted e) {
            return head(e.nanos(), "event-emitted") + ",\"agent\":" + e.agent() + ",\"name\":" + string(e.event())
                    + ",\"block\":" + string(e.block()) + ",\"message\":" + string(e.message())
                    + ",\"receivers\":" + e.receivers();
        }
        if (event instanceof TraceEvent.EventReacted e) {
            return head(e.nanos(), "event-reacted") + ",\"agent\":" + e.agent() + ",\"name\":" + string(e.event())
                    + ",\"block\":" + string(e.block())
                    + ",\"reaction\":" + string(e.byDefault() ? "default" : e.event());
        }
        if (event instanceof TraceEvent.EventDropped e) {
            return head(e.nanos(), "event-dropped") + ",\"agent\":" + e.agent() + ",\"name\":" + string(e.event());
        }
        return invocationLine(event);
    }

    /** The lines of invocations: the primitive's name is under {@code "member"}. */
    private static String invocationLine(TraceEvent event) {
        if (event instanceof TraceEvent.InvocationMade e) {
            return head(e.nanos(), "invocation-made") + ",\"requester\":" + e.requester() + ",\"callee\":"
                    + e.callee() + ",\"member\":" + string(e.member());
        }
        if (event instanceof TraceEvent.InvocationServed e) {
            return head(e.nanos(), "invocation-served") + ",\"requester\":" + e.requester() + ",\"callee\":"
                    + e.callee() + ",\"member\":" + string(e.member());
        }
        if (event instanceof TraceEvent.CountermeasureFired e) {
            return head(e.nanos(), "countermeasure-fired") + ",\"agent\":" + e.agent() + ",\"callee\":"
                    + e.callee() + ",\"member\":" + string(e.member()) + ",\"block\":" + string(e.block());
        }
        TraceEvent.InvocationDenied e = (TraceEvent.InvocationDenied) event;
        return head(e.nanos(), "invocation-denied") + ",\"requester\":" + e.requester() + ",\"callee\":"
                + e.callee() + ",\"member\":" + string(e.member()) + ",\"state\":" + string(e.state());
    }

    /**
     * {@code ,"line":N,"source":"…"} for a source {@code "file.masl:N: statement"}; only the source if
     * it names no line, nothing if there is none.
     */
    private static String source(String source) {
        if (source == null) {
            return "";
        }
        Matcher position = POSITION.matcher(source);
        String line = position.lookingAt() ? ",\"line\":" + position.group(1) : "";
        return line + ",\"source\":" + string(source);
    }

    private static String head(long nanos, String event) {
        return "{\"nanos\":" + nanos + ",\"event\":" + string(event);
    }

    private static String membership(long nanos, String event, int agent, String block) {
        return head(nanos, event) + ",\"agent\":" + agent + ",\"block\":" + string(block);
    }

    private static String string(String text) {
        if (text == null) {
            return "null";
        }
        StringBuilder json = new StringBuilder("\"");
        for (char c : text.toCharArray()) {
            switch (c) {
                case '"' -> json.append("\\\"");
                case '\\' -> json.append("\\\\");
                case '\n' -> json.append("\\n");
                case '\r' -> json.append("\\r");
                case '\t' -> json.append("\\t");
                default -> {
                    if (c < 0x20) {
                        json.append(String.format("\\u%04x", (int) c));
                    } else {
                        json.append(c);
                    }
                }
            }
        }
        return json.append('"').toString();
    }
}
