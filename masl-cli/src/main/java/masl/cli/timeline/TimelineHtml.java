package masl.cli.timeline;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Draws a {@link Timeline} as one self-contained HTML page: the timeline as JSON, and the inline
 * script and style that draw it as SVG (resources {@code timeline.js} and {@code timeline.css} of
 * this package), nothing fetched, so it opens anywhere, offline. The script draws one lane per agent
 * (its MASL name) over time, coloured by its innermost block, waves as bands above the lanes,
 * barrier trips, invocations as arrows from caller to callee, events from emitter to the agents
 * that reacted, failures; it zooms and pans (wheel, drag, a minimap of the whole run) and filters
 * by agent, block and kind of record.
 */
public final class TimelineHtml {

    private static final String[] PALETTE = {
        "#4e79a7", "#f28e2b", "#59a14f", "#e15759", "#76b7b2", "#edc948",
        "#b07aa1", "#ff9da7", "#9c755f", "#bab0ac", "#1f77b4", "#8c564b",
    };
    private static final ObjectMapper JSON = new ObjectMapper(new JsonFactory().setCharacterEscapes(new ScriptDataEscapes()));

    private final Timeline timeline;
    private final String title;
    private final List<String> blocks;

    public TimelineHtml(Timeline timeline, String title) {
        this.timeline = timeline;
        this.title = title;
        this.blocks = new ArrayList<>(timeline.blocks());
    }

    public String render() {
        return """
                <!DOCTYPE html>
                <html lang="en">
                <head>
                <meta charset="utf-8">
                <title>%s</title>
                <style>
                %s</style>
                </head>
                <body>
                <h1>%s</h1>
                <div id="summary" class="summary"></div>
                <div id="controls"></div>
                <svg id="minimap" xmlns="http://www.w3.org/2000/svg" role="img" aria-label="the whole run"></svg>
                <svg id="chart" xmlns="http://www.w3.org/2000/svg" role="img" aria-label="timeline"></svg>
                <div id="legend" aria-label="what the marks mean"></div>
                <p class="help">Wheel: zoom around the pointer. Drag: pan. Minimap: click or drag to move the view.
                Hover a shape for its record and MASL line.</p>
                <script type="application/json" id="timeline-data">%s</script>
                <script>
                %s</script>
                </body>
                </html>
                """.formatted(escape(title), resource("timeline.css"), escape(title), data(), resource("timeline.js"));
    }

    /** The colour of {@code block}'s spans, as {@code #rrggbb}. */
    public String color(String block) {
        int index = blocks.indexOf(block);
        return PALETTE[Math.floorMod(index, PALETTE.length)];
    }

    /** The timeline as JSON, times relative to its start, escaped so that no string can end or change its script element. */
    private String data() {
        Map<String, Object> data = new LinkedHashMap<>();
        data.put("clock", timeline.inRecordOrder() ? "record" : "nanos");
        data.put("length", timeline.end() - timeline.start());
        data.put("status", timeline.status());
        List<Map<String, Object>> agents = new ArrayList<>();
        timeline.agents().forEach((id, name) -> {
            List<Object[]> spans = new ArrayList<>();
            timeline.lanes().getOrDefault(id, List.of()).forEach(span -> spans.add(new Object[] {
                t(span.start()), t(span.end()), blocks.indexOf(span.block()), span.state().ordinal()}));
            agents.add(Map.of("id", id, "name", name, "spans", spans));
        });
        data.put("agents", agents);
        data.put("blocks", blocks.stream().map(block -> Map.of("name", block, "color", color(block))).toList());
        data.put("waves", timeline.waves().stream().map(wave -> new Object[] {
            blocks.indexOf(wave.block()), wave.wave(), t(wave.start()), t(wave.end())}).toList());
        data.put("trips", timeline.trips().stream().map(trip -> new Object[] {t(trip.nanos()), trip.domain(), trip.agents()}).toList());
        data.put("invocations", timeline.invocations().stream().map(call -> record(
                "made", t(call.made()), "resolved", t(call.resolved()), "from", call.requester(), "to", call.callee(),
                "member", call.member(), "outcome", lower(call.outcome()), "state", call.state(), "source", call.source())).toList());
        data.put("events", timeline.events().stream().map(event -> record(
                "t", t(event.nanos()), "agent", event.agent(), "name", event.name(), "kind", lower(event.kind()),
                "detail", event.detail(), "emission", event.emission(), "source", event.source())).toList());
        data.put("failures", timeline.failures().stream().map(failure -> record(
                "t", t(failure.nanos()), "agent", failure.agent(), "cause", failure.cause(), "source", failure.source())).toList());
        data.put("markers", timeline.markers().stream().map(marker -> record(
                "t", t(marker.nanos()), "agent", marker.agent(), "kind", marker.kind(), "label", marker.label(),
                "source", marker.source())).toList());
        try {
            return JSON.writeValueAsString(data);
        } catch (JsonProcessingException cannot) {
            throw new IllegalStateException("the timeline cannot be written as JSON", cannot);
        }
    }

    private long t(long time) {
        return time - timeline.start();
    }

    private static String lower(Enum<?> value) {
        return value.name().toLowerCase(Locale.ROOT);
    }

    /** A JSON object of the name-value pairs, in order, without the null values. */
    private static Map<String, Object> record(Object... pairs) {
        Map<String, Object> fields = new LinkedHashMap<>();
        for (int i = 0; i < pairs.length; i += 2) {
            if (pairs[i + 1] != null) {
                fields.put((String) pairs[i], pairs[i + 1]);
            }
        }
        return fields;
    }

    private static String resource(String name) {
        try (InputStream in = TimelineHtml.class.getResourceAsStream(name)) {
            if (in == null) {
                throw new IllegalStateException("resource " + name + " of the timeline is missing");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException unreadable) {
            throw new UncheckedIOException(unreadable);
        }
    }

    private static String escape(String text) {
        StringBuilder escaped = new StringBuilder(text.length());
        for (char c : text.toCharArray()) {
            switch (c) {
                case '<' -> escaped.append("&lt;");
                case '>' -> escaped.append("&gt;");
                case '&' -> escaped.append("&amp;");
                case '"' -> escaped.append("&quot;");
                default -> escaped.append(c);
            }
        }
        return escaped.toString();
    }
}
