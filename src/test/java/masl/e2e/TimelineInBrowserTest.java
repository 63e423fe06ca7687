package masl.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import masl.cli.timeline.Timeline;
import masl.cli.timeline.TimelineHtml;
import masl.cli.timeline.TraceReader;
import org.junit.jupiter.api.Test;

/**
 * {@code masl run --trace} then {@code masl timeline}, and the page opened in a real browser
 * (Debian's headless Chromium, installed by {@code tools/ensure-chromium.sh}); the screenshot is
 * kept in {@code build/timeline/} for a person to look at. The run is seeded, so the page (laid out
 * in record order, the clock being virtual) and its picture are the same every time.
 */
class TimelineInBrowserTest {

    private static final int MAIN_BLUE = 0x4e79a7;
    private static final int EVENS_ORANGE = 0xf28e2b;
    private static final int END_GREEN = 0x59a14f;
    private static final int TRIP_RED = 0xd62728;

    @Test
    void theTimelineOfExampleE3RendersItsLanesBlocksAndTrips() throws Exception {
        Path out = Files.createDirectories(Path.of("build/timeline"));
        Path trace = out.resolve("e3.jsonl");
        Path page = out.resolve("e3.html");
        Path screenshot = out.resolve("e3.png");
        Files.deleteIfExists(screenshot);

        assertEquals(0, masl("run", "src/test/resources/examples/e3_asynchronous_child.masl", "--seed", "3", "--trace", trace.toString()));
        assertEquals(0, masl("timeline", trace.toString(), "-o", page.toString()));
        chromiumScreenshot(page, screenshot);

        BufferedImage image = ImageIO.read(screenshot.toFile());
        assertTrue(pixelsOf(image, MAIN_BLUE) > 2_000, "the lanes of block main are drawn");
        assertTrue(pixelsOf(image, EVENS_ORANGE) > 500, "the agents in block evens are drawn");
        assertTrue(pixelsOf(image, END_GREEN) > 300, "the agent running scalar block end is drawn");
        assertTrue(pixelsOf(image, TRIP_RED) > 10, "barrier trips are drawn (one-pixel lines)");
    }

    @Test
    void theTimelineOfExampleE6ShowsThreeSeparateTurns() throws Exception {
        Path out = Files.createDirectories(Path.of("build/timeline"));
        Path trace = out.resolve("e6.jsonl");
        Path page = out.resolve("e6.html");
        Path screenshot = out.resolve("e6.png");
        Files.deleteIfExists(screenshot);

        assertEquals(0, masl("run", "src/test/resources/examples/e6_one_at_a_time.masl", "--seed", "5", "--trace", trace.toString()));
        assertEquals(0, masl("timeline", trace.toString(), "-o", page.toString()));
        chromiumScreenshot(page, screenshot);

        Timeline timeline;
        try (var text = Files.newBufferedReader(trace)) {
            timeline = Timeline.of(TraceReader.read(trace.toString(), text));
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
        assertTrue(pixelsOf(ImageIO.read(screenshot.toFile()), turnColour) > 3 * 50, "three turns are drawn");
    }

    private static int masl(String... args) {
        MaslCommand run = MaslCommand.run(args);
        assertEquals("", run.err());
        return run.status();
    }

    private static void chromiumScreenshot(Path page, Path screenshot) throws IOException, InterruptedException {
        String chromium = new File("/usr/bin/chromium").canExecute() ? "/usr/bin/chromium" : "chromium";
        Process browser;
        try {
            browser = new ProcessBuilder(chromium, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
                    "--window-size=1280,320", "--screenshot=" + screenshot.toAbsolutePath(), page.toAbsolutePath().toUri().toString())
                    .redirectErrorStream(true)
                    .redirectOutput(ProcessBuilder.Redirect.DISCARD)
                    .start();
        } catch (IOException missing) {
            throw new AssertionError("this test needs Debian's chromium: run tools/ensure-chromium.sh (./run-tests does)", missing);
        }
        if (!browser.waitFor(60, TimeUnit.SECONDS)) {
            browser.destroyForcibly();
            throw new AssertionError("chromium did not finish the screenshot in 60 s");
        }
        assertTrue(Files.size(screenshot) > 0, "chromium wrote " + screenshot);
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
