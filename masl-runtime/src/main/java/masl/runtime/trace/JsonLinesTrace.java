package masl.runtime.trace;

import java.io.Flushable;
import java.io.IOException;
import java.io.UncheckedIOException;

/**
 * Writes one JSON object per line for every event (components.md, "Runtime"), in the order they
 * happened, for {@code --trace FILE}: for instance
 * {@code {"nanos":123,"event":"left","agent":2,"block":"work","cause":"reelect"}}. Names are
 * written as JSON strings, escaped; a MASL event's own name goes under {@code "name"}, as in
 * {@code {"nanos":124,"event":"event-reacted","agent":1,"name":"go","block":"main","reaction":"go"}}.
 * Source positions are not known to the runtime yet.
 */
public final class JsonLinesTrace implements Trace, Flushable {

    private final Appendable out;

    public JsonLinesTrace(Appendable out) {
        this.out = out;
    }

    @Override
    public synchronized void record(TraceEvent event) {
        String line;
        if (event instanceof TraceEvent.Entered e) {
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
        try {
            out.append(line).append("}\n");
        } catch (IOException e) {
            throw new UncheckedIOException("trace output failed", e);
        }
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
