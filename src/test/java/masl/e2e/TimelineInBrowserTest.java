package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import masl.cli.timeline.Timeline;
import masl.cli.timeline.TimelineHtml;
import masl.cli.timeline.TraceReader;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

/**
 * {@code masl run --trace} (or {@code --sim}) then {@code masl timeline}, and the page opened in a
 * real browser (Debian's headless Chromium, driven by {@link ChromiumPage}): what it draws is read
 * from its DOM and its pixels, zoom, pan and filters are used with the mouse. The screenshots are
 * kept in {@code build/timeline/} for a person to look at (docs/timeline.md shows the sweep's). The
 * in-process runs are seeded, so their pages (laid out in record order, the clock being virtual)
 * are the same every time; the sweep runs in lock-step, the same every time too.
 */
@Tag("slow")
class TimelineInBrowserTest {

    private static final int MAIN_BLUE = 0x4e79a7;
    private static final int EVENS_ORANGE = 0xf28e2b;
    private static final int END_GREEN = 0x59a14f;
    private static final int TRIP_RED = 0xd62728;
    private static final int EMIT_PURPLE = 0x6a3d9a;
    private static final int DENIED_RED = 0xcc0000;
    private static final Path OUT = Path.of("build/timeline");

    @Test
    void theTimelineOfExampleE3RendersItsLanesBlocksAndTrips() throws Exception {
        Path page = runAndDraw("e3", "src/test/resources/examples/e3_asynchronous_child.masl", "--seed", "3");
        try (ChromiumPage browser = ChromiumPage.open(page, 1280, 600)) {
            BufferedImage image = browser.screenshot(OUT.resolve("e3.png"));
            assertTrue(pixelsOf(image, MAIN_BLUE) > 2_000, "the lanes of block main are drawn");
            assertTrue(pixelsOf(image, EVENS_ORANGE) > 500, "the agents in block evens are drawn");
            assertTrue(pixelsOf(image, END_GREEN) > 300, "the agent running scalar block end is drawn");
            assertTrue(pixelsOf(image, TRIP_RED) > 10, "barrier trips are drawn (one-pixel lines)");
        }
    }

    @Test
    void theTimelineOfExampleE6ShowsThreeSeparateTurns() throws Exception {
        Path page = runAndDraw("e6", "src/test/resources/examples/e6_one_at_a_time.masl", "--seed", "5");
        Timeline timeline;
        try (var text = Files.newBufferedReader(OUT.resolve("e6.jsonl"))) {
            timeline = Timeline.of(TraceReader.read("e6.jsonl", text));
        }
        List<Timeline.Span> turns = timeline.lanes().values().stream().flatMap(List::stream)
                .filter(span -> span.block().equals("turn") && span.state() == Timeline.State.RUNNING)
                .sorted(Comparator.comparingLong(Timeline.Span::start))
                .toList();
        assertEquals(3, turns.size(), turns::toString);
        for (int i = 1; i < turns.size(); i++) {
            assertTrue(turns.get(i - 1).end() <= turns.get(i).start(), "turns overlap: " + turns);
        }
        int turnColour = Integer.parseInt(new TimelineHtml(timeline, "").color("turn").substring(1), 16);
        try (ChromiumPage browser = ChromiumPage.open(page, 1280, 600)) {
            assertTrue(pixelsOf(browser.screenshot(OUT.resolve("e6.png")), turnColour) > 3 * 50, "three turns are drawn");
        }
    }

    @Test
    void exampleE4DrawsTheEmissionLinkedToEachReactionOnNamedLanes() throws Exception {
        Path page = runAndDraw("e4", "src/test/resources/examples/e4_events.masl", "--seed", "4");
        try (ChromiumPage browser = ChromiumPage.open(page, 1280, 600)) {
            assertEquals(List.of("leader", "w1", "w2", "w3"), texts(browser, "#chart text.agent"));
            assertEquals(1, count(browser, "#chart path.emitted"), "go is emitted once");
            assertEquals(4, count(browser, "#chart path.reacted"), "every agent reacts to go");
            assertTrue(count(browser, "#chart line.event-link") >= 3, "the workers' reactions are linked to the emission");
            assertTrue(texts(browser, "#chart text.label").contains("emit go"), "the emission is named on its lane");
            assertNoBlockNamedNull(browser);
            assertTrue(pixelsOf(browser.screenshot(OUT.resolve("e4.png")), EMIT_PURPLE) > 30, "the events are drawn");
        }
    }

    @Test
    void exampleE5DrawsTheDeniedInvocationAndTheTimeoutEventNotABlock() throws Exception {
        Path page = runAndDraw("e5", "src/test/resources/examples/e5_permeability.masl", "--seed", "5");
        try (ChromiumPage browser = ChromiumPage.open(page, 1280, 600)) {
            assertEquals(List.of("a", "b"), texts(browser, "#chart text.agent"));
            assertEquals(1, count(browser, "#chart line.invocation.denied"), "a's call of b.getProxyID is drawn, denied");
            assertTrue(texts(browser, "#chart text.label").contains("\u2192 b.getProxyID denied (nothing)"),
                    texts(browser, "#chart text.label").toString());
            assertTrue(texts(browser, "#chart text.label").contains("emit timeout"), "the system event is an event");
            assertEquals(List.of("main"), texts(browser, ".filter-block label"), "the blocks: timeout is none");
            assertNoBlockNamedNull(browser);
            assertTrue(pixelsOf(browser.screenshot(OUT.resolve("e5.png")), DENIED_RED) > 20, "the denied call is drawn red");
        }
    }

    @Test
    void theSweepMissionShowsTheFailOverAndZoomsPansAndFilters() throws Exception {
        Path out = Files.createDirectories(OUT);
        Path simOut = out.resolve("sweep");
        MaslCommand run = MaslCommand.run("run", "--sim", "missions/sweep-leader-fault.scenario.xml", "--out", simOut.toString());
        assertEquals(0, run.status(), run::toString);
        Path page = out.resolve("sweep.html");
        assertEquals(0, masl("timeline", simOut.resolve("trace.jsonl").toString(), "-o", page.toString()));
        try (ChromiumPage browser = ChromiumPage.open(page, 1400, 560)) {
            assertEquals(List.of("k0", "k1", "k2", "k3"), texts(browser, "#chart text.agent"));
            assertTrue(titles(browser, "#chart rect.left-mark").stream().anyMatch(t -> t.startsWith("k0: left main (end) at 3.05")),
                    "the failed k0 leaves main at 3.05 s: " + titles(browser, "#chart rect.left-mark"));
            assertTrue(titles(browser, "#chart path.entry-mark").stream().anyMatch(t -> t.startsWith("k1: enters lead at 3.05")),
                    "k1 leads from 3.05 s");
            assertEquals(List.of("\u2192 k3.getY"), texts(browser, "#chart text.label.invocations"), "the new leader's getY call");
            assertLabelsWhole(browser);
            browser.screenshot(out.resolve("sweep-whole.png"));

            double[] whole = view(browser);
            int chartY = browser.evaluate("(() => { const r = document.getElementById('chart').getBoundingClientRect();"
                    + " return Math.round(r.top + r.height / 2); })()").asInt();
            for (int turn = 0; turn < 2; turn++) {
                browser.wheel(xOf(browser, 4.0e9), chartY, -250);
            }
            double[] zoomed = view(browser);
            assertTrue(zoomed[1] - zoomed[0] < (whole[1] - whole[0]) / 2, "the wheel zooms in: " + zoomed[0] + " - " + zoomed[1]);
            assertTrue(zoomed[0] < 3.0e9 && zoomed[1] > 7.8e9, "around the pointer: the fail-over and the getY call stay in view");
            assertFalse(text(browser, "#interval").contains("0.00 s \u2013 23.60 s"), text(browser, "#interval"));
            assertLabelsWhole(browser);
            BufferedImage failOver = browser.screenshot(out.resolve("sweep-fail-over.png"));
            assertTrue(pixelsOf(failOver, END_GREEN) > 500, "the leaders' lead blocks are drawn when zoomed in");
            assertTrue(pixelsOf(failOver, EVENS_ORANGE) > 5_000, "the robots' blocks are drawn");

            browser.drag(700, 900, chartY);
            double[] panned = view(browser);
            assertTrue(panned[0] < zoomed[0], "dragging right shows earlier times");
            assertEquals(zoomed[1] - zoomed[0], panned[1] - panned[0], 1e-3 * (zoomed[1] - zoomed[0]), "panning keeps the zoom");

            browser.click(".filter-agent input[value='2']");
            assertEquals(List.of("k0", "k1", "k3"), texts(browser, "#chart text.agent"), "unticking k2 hides its lane");
            browser.click(".filter-kind input[value='invocations']");
            assertEquals(0, count(browser, "#chart .invocation"), "unticking invocations hides them");
        }
    }

    /** Under the chart, a legend says what each mark means, each mark drawn as the chart draws it. */
    @Test
    void aLegendUnderTheChartExplainsEveryMark() throws Exception {
        Path page = runAndDraw("e4-legend", "src/test/resources/examples/e4_events.masl", "--seed", "4");
        try (ChromiumPage browser = ChromiumPage.open(page, 1280, 700)) {
            assertEquals(List.of("an agent in its innermost block (the block\u2019s colour)",
                    "held at the block\u2019s entry or exit barrier", "a wave of the block (above the lanes)",
                    "a barrier trip", "an invocation, from the caller to the callee (dashed while pending)",
                    "an invocation denied by the callee\u2019s permeability state", "an event emitted",
                    "a reaction to an event", "an agent\u2019s program died",
                    "an agent entering a nested block for the first time", "an agent leaving its outermost block",
                    "a countermeasure fired"), texts(browser, "#legend span"));
            assertEquals(1, count(browser, "#legend span.legend-held rect[fill='url(#legend-hatch)']"), "held is hatched");
            BufferedImage image = browser.screenshot(OUT.resolve("e4-legend.png"));
            JsonNode box = browser.evaluate("(() => { const r = document.getElementById('legend').getBoundingClientRect();"
                    + " return [r.left, r.top, r.width, r.height].map(Math.round); })()");
            BufferedImage legend = image.getSubimage(box.get(0).asInt(), box.get(1).asInt(), box.get(2).asInt(),
                    box.get(3).asInt());
            assertTrue(pixelsOf(legend, TRIP_RED) > 5, "the trip's line");
            assertTrue(pixelsOf(legend, EMIT_PURPLE) > 10, "the emission's triangle");
            assertTrue(pixelsOf(legend, DENIED_RED) > 5, "the denied invocation");
        }
    }

    private static Path runAndDraw(String name, String program, String... options) throws Exception {
        Path out = Files.createDirectories(OUT);
        Path trace = out.resolve(name + ".jsonl");
        Path page = out.resolve(name + ".html");
        List<String> words = new ArrayList<>(List.of("run", program, "--trace", trace.toString()));
        words.addAll(List.of(options));
        assertEquals(0, masl(words.toArray(String[]::new)));
        assertEquals(0, masl("timeline", trace.toString(), "-o", page.toString()));
        return page;
    }

    private static void assertNoBlockNamedNull(ChromiumPage browser) throws Exception {
        assertFalse(browser.evaluate("document.body.innerText").asText().contains("null"), "no block named null on the page");
        assertEquals(0, count(browser, "[data-block='null']"), "no shape of a block named null");
    }

    /** Every label of the time axis lies within the chart: none is cut off. */
    private static void assertLabelsWhole(ChromiumPage browser) throws Exception {
        JsonNode outside = browser.evaluate("(() => { const c = document.getElementById('chart').getBoundingClientRect();"
                + " return [...document.querySelectorAll('#chart text.axis')].filter(t => { const r = t.getBoundingClientRect();"
                + " return r.left < c.left + 1 || r.right > c.right - 1; }).map(t => t.textContent); })()");
        assertEquals(0, outside.size(), "axis labels cut off: " + outside);
        assertTrue(count(browser, "#chart text.axis") >= 3, "the axis is labelled");
    }

    private static double[] view(ChromiumPage browser) throws Exception {
        JsonNode view = browser.evaluate("(() => { const c = document.getElementById('chart');"
                + " return [Number(c.dataset.viewStart), Number(c.dataset.viewEnd)]; })()");
        return new double[] {view.get(0).asDouble(), view.get(1).asDouble()};
    }

    /** The horizontal position in the viewport of time {@code t} (nanoseconds from the start). */
    private static int xOf(ChromiumPage browser, double t) throws Exception {
        return browser.evaluate("(() => { const c = document.getElementById('chart'); const d = c.dataset;"
                + " const left = Number(d.plotLeft), right = Number(d.plotRight), s = Number(d.viewStart), e = Number(d.viewEnd);"
                + " return Math.round(c.getBoundingClientRect().left + left + (" + t + " - s) * (right - left) / (e - s)); })()").asInt();
    }

    private static int count(ChromiumPage browser, String selector) throws Exception {
        return browser.evaluate("document.querySelectorAll(\"" + selector.replace("\"", "\\\"") + "\").length").asInt();
    }

    private static String text(ChromiumPage browser, String selector) throws Exception {
        return browser.evaluate("document.querySelector(\"" + selector + "\").textContent").asText();
    }

    private static List<String> texts(ChromiumPage browser, String selector) throws Exception {
        return strings(browser.evaluate("[...document.querySelectorAll(\"" + selector + "\")].map(e => [...e.childNodes]"
                + ".filter(n => n.nodeType === Node.TEXT_NODE || n.nodeName === 'LABEL').map(n => n.textContent).join('').trim())"));
    }

    private static List<String> titles(ChromiumPage browser, String selector) throws Exception {
        return strings(browser.evaluate("[...document.querySelectorAll(\"" + selector + "\")].map(e => e.querySelector('title').textContent)"));
    }

    private static List<String> strings(JsonNode array) {
        List<String> all = new ArrayList<>();
        array.forEach(item -> all.add(item.asText()));
        return all;
    }

    private static int masl(String... args) {
        MaslCommand run = MaslCommand.run(args);
        assertEquals("", run.err(), run::toString);
        return run.status();
    }

    private static int pixelsOf(BufferedImage image, int rgb) {
        int count = 0;
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                if ((image.getRGB(x, y) & 0xffffff) == rgb) {
                    count++;
                }
            }
        }
        return count;
    }
}
