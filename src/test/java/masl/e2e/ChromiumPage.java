package masl.e2e;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.io.File;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.net.http.WebSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Base64;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Stream;
import javax.imageio.ImageIO;

/**
 * A page opened in Debian's headless Chromium (installed by {@code tools/ensure-chromium.sh}) and
 * driven through the DevTools protocol over its WebSocket, with the JDK's own HTTP client: evaluate
 * script in the page, send real wheel and mouse events, take screenshots. The browser runs with a
 * fresh profile and no background networking (the flags this machine needs) and is closed with
 * the page.
 */
final class ChromiumPage implements AutoCloseable {

    private static final ObjectMapper JSON = new ObjectMapper();
    private static final Duration WAIT = Duration.ofSeconds(60);

    private final Process browser;
    private final Path profile;
    private final WebSocket socket;
    private final Replies replies;
    private final AtomicInteger ids = new AtomicInteger();

    private ChromiumPage(Process browser, Path profile, WebSocket socket, Replies replies) {
        this.browser = browser;
        this.profile = profile;
        this.socket = socket;
        this.replies = replies;
    }

    /** Opens {@code page} in a viewport of {@code width} by {@code height} pixels, once it has loaded. */
    static ChromiumPage open(Path page, int width, int height) throws Exception {
        String chromium = new File("/usr/bin/chromium").canExecute() ? "/usr/bin/chromium" : "chromium";
        Path profile = Files.createTempDirectory("masl-chromium");
        Process browser;
        try {
            browser = new ProcessBuilder(chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                    "--no-first-run", "--disable-background-networking", "--disable-component-update", "--disable-sync",
                    "--hide-scrollbars", "--user-data-dir=" + profile, "--remote-debugging-port=0",
                    "--window-size=" + width + "," + height, "about:blank")
                    .redirectErrorStream(true)
                    .redirectOutput(ProcessBuilder.Redirect.DISCARD)
                    .start();
        } catch (IOException missing) {
            throw new AssertionError("this test needs Debian's chromium: run tools/ensure-chromium.sh (./run-tests does)", missing);
        }
        try {
            int port = devToolsPort(profile, browser);
            HttpClient http = HttpClient.newHttpClient();
            JsonNode targets = JSON.readTree(http.send(HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + port + "/json/list")).build(),
                    HttpResponse.BodyHandlers.ofString()).body());
            String address = null;
            for (JsonNode target : targets) {
                if (target.path("type").asText().equals("page")) {
                    address = target.path("webSocketDebuggerUrl").asText();
                }
            }
            if (address == null) {
                throw new AssertionError("chromium opened no page: " + targets);
            }
            Replies replies = new Replies();
            WebSocket socket = http.newWebSocketBuilder().buildAsync(URI.create(address), replies)
                    .get(WAIT.toSeconds(), TimeUnit.SECONDS);
            ChromiumPage connected = new ChromiumPage(browser, profile, socket, replies);
            connected.call("Emulation.setDeviceMetricsOverride",
                    Map.of("width", width, "height", height, "deviceScaleFactor", 1, "mobile", false));
            connected.call("Page.navigate", Map.of("url", page.toAbsolutePath().toUri().toString()));
            connected.waitUntil("document.readyState === 'complete' && document.getElementById('interval') !== null");
            connected.nextFrames();
            return connected;
        } catch (Exception | AssertionError failed) {
            browser.destroyForcibly();
            deleteTree(profile);
            throw failed;
        }
    }

    /** The value of the script {@code expression} (awaited if a promise), as JSON. */
    JsonNode evaluate(String expression) throws Exception {
        JsonNode reply = call("Runtime.evaluate", Map.of("expression", expression, "returnByValue", true, "awaitPromise", true));
        if (reply.has("exceptionDetails")) {
            throw new AssertionError("the page's script failed: " + reply.get("exceptionDetails"));
        }
        return reply.path("result").path("value");
    }

    /** A turn of the mouse wheel at ({@code x}, {@code y}); negative {@code deltaY} zooms in. */
    void wheel(int x, int y, int deltaY) throws Exception {
        call("Input.dispatchMouseEvent", Map.of("type", "mouseWheel", "x", x, "y", y, "deltaX", 0, "deltaY", deltaY));
        nextFrames();
    }

    /** Presses the left button at ({@code x0}, {@code y}), moves to {@code x1} and releases it. */
    void drag(int x0, int x1, int y) throws Exception {
        call("Input.dispatchMouseEvent", Map.of("type", "mousePressed", "x", x0, "y", y, "button", "left", "clickCount", 1));
        for (int step = 1; step <= 5; step++) {
            call("Input.dispatchMouseEvent", Map.of("type", "mouseMoved", "x", x0 + (x1 - x0) * step / 5, "y", y, "button", "left"));
        }
        call("Input.dispatchMouseEvent", Map.of("type", "mouseReleased", "x", x1, "y", y, "button", "left", "clickCount", 1));
        nextFrames();
    }

    /** Clicks the element {@code selector} names, at its centre, with the mouse. */
    void click(String selector) throws Exception {
        JsonNode box = evaluate("(() => { const r = document.querySelector(" + JSON.writeValueAsString(selector)
                + ").getBoundingClientRect(); return [r.left + r.width / 2, r.top + r.height / 2]; })()");
        int x = (int) Math.round(box.get(0).asDouble());
        int y = (int) Math.round(box.get(1).asDouble());
        call("Input.dispatchMouseEvent", Map.of("type", "mousePressed", "x", x, "y", y, "button", "left", "clickCount", 1));
        call("Input.dispatchMouseEvent", Map.of("type", "mouseReleased", "x", x, "y", y, "button", "left", "clickCount", 1));
        nextFrames();
    }

    /** The viewport as it is drawn now, also written to {@code file} for a person to look at. */
    BufferedImage screenshot(Path file) throws Exception {
        byte[] png = Base64.getDecoder().decode(call("Page.captureScreenshot", Map.of("format", "png")).path("data").asText());
        Files.write(file, png);
        return ImageIO.read(new ByteArrayInputStream(png));
    }

    /** Waits until the page has drawn what the last input asked for (it redraws on an animation frame). */
    private void nextFrames() throws Exception {
        evaluate("new Promise(done => requestAnimationFrame(() => requestAnimationFrame(() => done(true))))");
    }

    private void waitUntil(String condition) throws Exception {
        long deadline = System.nanoTime() + WAIT.toNanos();
        while (!evaluate(condition).asBoolean(false)) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("the page never reached: " + condition);
            }
            Thread.sleep(50);
        }
    }

    private JsonNode call(String method, Map<String, Object> params) throws Exception {
        int id = ids.incrementAndGet();
        CompletableFuture<JsonNode> reply = new CompletableFuture<>();
        replies.waiting.put(id, reply);
        ObjectNode message = JSON.createObjectNode().put("id", id).put("method", method);
        message.set("params", JSON.valueToTree(params));
        socket.sendText(JSON.writeValueAsString(message), true).get(WAIT.toSeconds(), TimeUnit.SECONDS);
        JsonNode answer = reply.get(WAIT.toSeconds(), TimeUnit.SECONDS);
        if (answer.has("error")) {
            throw new AssertionError(method + " failed: " + answer.get("error"));
        }
        return answer.path("result");
    }

    /** Matches each reply of the browser to its call by id; events are ignored. */
    private static final class Replies implements WebSocket.Listener {
        private final Map<Integer, CompletableFuture<JsonNode>> waiting = new ConcurrentHashMap<>();
        private final StringBuilder text = new StringBuilder();

        @Override
        public CompletionStage<?> onText(WebSocket webSocket, CharSequence data, boolean last) {
            text.append(data);
            if (last) {
                try {
                    JsonNode message = JSON.readTree(text.toString());
                    if (message.has("id")) {
                        CompletableFuture<JsonNode> reply = waiting.remove(message.get("id").asInt());
                        if (reply != null) {
                            reply.complete(message);
                        }
                    }
                } catch (IOException malformed) {
                    throw new IllegalStateException("chromium sent malformed JSON", malformed);
                }
                text.setLength(0);
            }
            webSocket.request(1);
            return null;
        }
    }

    private static int devToolsPort(Path profile, Process browser) throws Exception {
        Path active = profile.resolve("DevToolsActivePort");
        long deadline = System.nanoTime() + WAIT.toNanos();
        while (System.nanoTime() < deadline) {
            if (Files.isRegularFile(active)) {
                List<String> lines = Files.readAllLines(active);
                if (!lines.isEmpty() && !lines.get(0).isBlank()) {
                    return Integer.parseInt(lines.get(0).trim());
                }
            }
            if (!browser.isAlive()) {
                throw new AssertionError("chromium exited with status " + browser.exitValue() + " before it listened");
            }
            Thread.sleep(50);
        }
        throw new AssertionError("chromium did not open its DevTools port in " + WAIT.toSeconds() + " s");
    }

    @Override
    public void close() throws Exception {
        try {
            call("Browser.close", Map.of());
        } catch (Exception | AssertionError alreadyGone) {
            // The browser is stopped below anyway.
        }
        List<ProcessHandle> all = new ArrayList<>(browser.descendants().toList());
        all.add(browser.toHandle());
        for (ProcessHandle process : all) {
            process.destroy();
        }
        for (ProcessHandle process : all) {
            try {
                process.onExit().get(10, TimeUnit.SECONDS);
            } catch (TimeoutException stuck) {
                process.destroyForcibly();
            }
        }
        deleteTree(profile);
    }

    /** Deletes the browser's profile; what a process still writing keeps there is left to the system's cleaning of /tmp. */
    private static void deleteTree(Path folder) {
        try (Stream<Path> files = Files.walk(folder)) {
            for (Path file : files.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(file);
            }
        } catch (IOException | UncheckedIOException notAllGone) {
            System.err.println("ChromiumPage: could not delete all of " + folder + ": " + notAllGone);
        }
    }
}
