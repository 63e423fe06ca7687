package masl.runtime.trace;

import java.io.Flushable;
import java.io.IOException;
import java.io.UncheckedIOException;
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
 */
public final class JsonLinesTrace implements Trace, Flushable {

    /** The line in a source {@code "file.masl:14: …"}: the number after the file's name. */
    private static final Pattern POSITION = Pattern.compile("[^:]*:(\\d+):");

    private final Appendable out;
    /** {@code mission-ended} was written: it stays the last line, whatever agents still finishing record. */
    private boolean ended;

    public JsonLinesTrace(Appendable out) {
        this.out = out;
    }

    @Override
    public synchronized void record(TraceEvent event) {
        if (ended) {
            return;
        }
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
        try {
            out.append(line).append(source(event.source())).append("}\n");
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
