package masl.cli.timeline;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Draws a {@link Timeline} as one self-contained HTML page: inline CSS and SVG, no script, nothing
 * fetched, so it opens anywhere, offline. One lane per agent over time, coloured by its innermost
 * block (hatched while held at the block's entry or exit barrier); barrier trips as vertical lines;
 * each block's waves as bands above the lanes; other records of an agent (events, invocations) as
 * marks on its lane. Every shape has a tooltip with its details.
 */
public final class TimelineHtml {

    private static final String[] PALETTE = {
        "#4e79a7", "#f28e2b", "#59a14f", "#e15759", "#76b7b2", "#edc948",
        "#b07aa1", "#ff9da7", "#9c755f", "#bab0ac", "#1f77b4", "#8c564b",
    };
    private static final int LABEL_WIDTH = 110;
    private static final int PLOT_WIDTH = 1100;
    private static final int LANE_HEIGHT = 22;
    private static final int WAVE_HEIGHT = 12;
    private static final int AXIS_HEIGHT = 28;
    /** Beyond this many trips, lines are drawn faint, or they would hide the lanes. */
    private static final int MANY_TRIPS = 200;

    private final Timeline timeline;
    private final String title;
    private final List<String> blocks;

    public TimelineHtml(Timeline timeline, String title) {
        this.timeline = timeline;
        this.title = title;
        this.blocks = new ArrayList<>(timeline.blocks());
    }

    public String render() {
        int waveRows = blocks.size();
        int lanesTop = AXIS_HEIGHT + waveRows * WAVE_HEIGHT + 8;
        int height = lanesTop + timeline.lanes().size() * LANE_HEIGHT + 10;
        StringBuilder svg = new StringBuilder();
        svg.append(String.format(Locale.ROOT,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" role=\"img\" aria-label=\"timeline\">%n",
                LABEL_WIDTH + PLOT_WIDTH + 20, height));
        svg.append("<defs><pattern id=\"hatch\" width=\"6\" height=\"6\" patternUnits=\"userSpaceOnUse\" patternTransform=\"rotate(45)\">"
                + "<rect width=\"6\" height=\"6\" fill=\"white\" fill-opacity=\"0.0\"/><line x1=\"0\" y1=\"0\" x2=\"0\" y2=\"6\" stroke=\"white\" stroke-width=\"3\"/></pattern></defs>\n");
        axis(svg, height);
        waves(svg);
        lanes(svg, lanesTop);
        trips(svg, lanesTop, height);
        markers(svg, lanesTop);
        svg.append("</svg>\n");
        return page(svg.toString());
    }

    private void axis(StringBuilder svg, int height) {
        double span = Math.max(1, timeline.end() - timeline.start());
        for (int tick = 0; tick <= 10; tick++) {
            double x = LABEL_WIDTH + PLOT_WIDTH * tick / 10.0;
            String label = timeline.inRecordOrder()
                    ? String.format(Locale.ROOT, "#%.0f", span * tick / 10)
                    : String.format(Locale.ROOT, "%.1f ms", span * tick / 10 / 1e6);
            svg.append(String.format(Locale.ROOT,
                    "<line class=\"tick\" x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\"/><text class=\"axis\" x=\"%.1f\" y=\"14\">%s</text>%n",
                    x, 18, x, height, x, escape(label)));
        }
    }

    private void waves(StringBuilder svg) {
        for (Timeline.WaveSpan wave : timeline.waves()) {
            int row = blocks.indexOf(wave.block());
            double x = x(wave.start());
            double width = Math.max(1.5, x(wave.end()) - x);
            svg.append(String.format(Locale.ROOT,
                    "<rect class=\"wave\" x=\"%.1f\" y=\"%d\" width=\"%.1f\" height=\"%d\" fill=\"%s\"><title>%s</title></rect>%n",
                    x, AXIS_HEIGHT + row * WAVE_HEIGHT, width, WAVE_HEIGHT - 3, color(wave.block()),
                    escape("block " + wave.block() + ", wave " + wave.wave())));
        }
        for (int row = 0; row < blocks.size(); row++) {
            svg.append(String.format(Locale.ROOT, "<text class=\"wavelabel\" x=\"%d\" y=\"%d\">waves %s</text>%n",
                    LABEL_WIDTH - 6, AXIS_HEIGHT + row * WAVE_HEIGHT + WAVE_HEIGHT - 4, escape(blocks.get(row))));
        }
    }

    private void lanes(StringBuilder svg, int top) {
        int row = 0;
        for (Map.Entry<Integer, List<Timeline.Span>> lane : timeline.lanes().entrySet()) {
            int y = top + row * LANE_HEIGHT;
            svg.append(String.format(Locale.ROOT, "<text class=\"agent\" x=\"%d\" y=\"%d\">agent %d</text>%n",
                    LABEL_WIDTH - 6, y + LANE_HEIGHT - 7, lane.getKey()));
            svg.append(String.format(Locale.ROOT, "<rect class=\"lane\" x=\"%d\" y=\"%d\" width=\"%d\" height=\"%d\"/>%n",
                    LABEL_WIDTH, y + 2, PLOT_WIDTH, LANE_HEIGHT - 4));
            for (Timeline.Span span : lane.getValue()) {
                double x = x(span.start());
                double width = Math.max(1.0, x(span.end()) - x);
                String tooltip = "agent " + lane.getKey() + ": " + span.block() + " ("
                        + span.state().name().toLowerCase(Locale.ROOT).replace('_', '-') + ")";
                svg.append(String.format(Locale.ROOT,
                        "<rect x=\"%.1f\" y=\"%d\" width=\"%.1f\" height=\"%d\" fill=\"%s\"><title>%s</title></rect>%n",
                        x, y + 2, width, LANE_HEIGHT - 4, color(span.block()), escape(tooltip)));
                if (span.state() != Timeline.State.RUNNING) {
                    svg.append(String.format(Locale.ROOT,
                            "<rect x=\"%.1f\" y=\"%d\" width=\"%.1f\" height=\"%d\" fill=\"url(#hatch)\"><title>%s</title></rect>%n",
                            x, y + 2, width, LANE_HEIGHT - 4, escape(tooltip)));
                }
            }
            row++;
        }
    }

    private void trips(StringBuilder svg, int top, int height) {
        String opacity = timeline.trips().size() > MANY_TRIPS ? "0.15" : "0.8";
        for (Timeline.Trip trip : timeline.trips()) {
            double x = x(trip.nanos());
            svg.append(String.format(Locale.ROOT,
                    "<line class=\"trip\" stroke-opacity=\"%s\" x1=\"%.1f\" y1=\"%d\" x2=\"%.1f\" y2=\"%d\"><title>%s</title></line>%n",
                    opacity, x, top, x, height - 10, escape("barrier trip, domain " + trip.domain() + ", " + trip.agents() + " agents")));
        }
    }

    private void markers(StringBuilder svg, int top) {
        List<Integer> agents = new ArrayList<>(timeline.lanes().keySet());
        for (Timeline.Marker marker : timeline.markers()) {
            int row = agents.indexOf(marker.agent());
            if (row < 0) {
                row = agents.size();
            }
            double x = x(marker.nanos());
            int y = top + row * LANE_HEIGHT;
            svg.append(String.format(Locale.ROOT,
                    "<path class=\"mark\" d=\"M %.1f %d l 5 -8 l -10 0 z\"><title>%s</title></path>%n",
                    x, y + 10, escape("agent " + marker.agent() + ": " + marker.label())));
        }
    }

    private String page(String svg) {
        StringBuilder legend = new StringBuilder();
        for (String block : blocks) {
            legend.append(String.format(Locale.ROOT, "<span class=\"key\"><i style=\"background:%s\"></i>%s</span>%n",
                    color(block), escape(block)));
        }
        legend.append("<span class=\"key\"><i class=\"hatched\"></i>held at an entry or exit barrier</span>\n")
                .append("<span class=\"key\"><i class=\"tripkey\"></i>barrier trip</span>\n")
                .append("<span class=\"key\"><i class=\"markkey\"></i>event or invocation</span>\n");
        String summary = String.format(Locale.ROOT, "%d agents, %d blocks, %d barrier trips, %d waves, %d events and invocations%s",
                timeline.lanes().size(), blocks.size(), timeline.trips().size(), timeline.waves().size(), timeline.markers().size(),
                timeline.inRecordOrder() ? "; every record bears one time (virtual clock), so time is the record number" : "");
        return """
                <!DOCTYPE html>
                <html lang="en">
                <head>
                <meta charset="utf-8">
                <title>%s</title>
                <style>
                body { font: 13px sans-serif; margin: 16px; color: #222; background: #fff; }
                h1 { font-size: 18px; margin: 0 0 4px 0; }
                .summary { color: #555; margin-bottom: 8px; }
                .key { display: inline-block; margin: 0 14px 6px 0; }
                .key i { display: inline-block; width: 14px; height: 12px; margin-right: 5px; vertical-align: -1px; }
                .key i.hatched { background: repeating-linear-gradient(45deg, #888, #888 3px, #fff 3px, #fff 6px); }
                .key i.tripkey { width: 2px; background: #d62728; }
                .key i.markkey { width: 0; height: 0; border-left: 6px solid transparent; border-right: 6px solid transparent; border-top: 10px solid #111; }
                svg text { font: 11px sans-serif; fill: #333; }
                text.agent, text.wavelabel { text-anchor: end; }
                text.axis { text-anchor: middle; fill: #666; }
                line.tick { stroke: #eee; }
                rect.lane { fill: #f4f4f4; }
                rect.wave { opacity: 0.55; }
                line.trip { stroke: #d62728; stroke-width: 1; }
                path.mark { fill: #111; }
                </style>
                </head>
                <body>
                <h1>%s</h1>
                <div class="summary">%s</div>
                <div class="legend">
                %s</div>
                %s</body>
                </html>
                """.formatted(escape(title), escape(title), escape(summary), legend, svg);
    }

    private double x(long time) {
        double span = Math.max(1, timeline.end() - timeline.start());
        return LABEL_WIDTH + PLOT_WIDTH * (time - timeline.start()) / span;
    }

    /** The colour of {@code block}'s spans, as {@code #rrggbb}. */
    public String color(String block) {
        int index = blocks.indexOf(block);
        return PALETTE[Math.floorMod(index, PALETTE.length)];
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
