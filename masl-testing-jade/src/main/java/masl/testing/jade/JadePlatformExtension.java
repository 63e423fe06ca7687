package masl.testing.jade;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import masl.jade.platform.JadeOptions;
import masl.jade.platform.JadePlatform;
import masl.jade.platform.JadeThreads;
import masl.testing.MissionPlatform;
import org.junit.jupiter.api.extension.AfterAllCallback;
import org.junit.jupiter.api.extension.AfterEachCallback;
import org.junit.jupiter.api.extension.BeforeAllCallback;
import org.junit.jupiter.api.extension.BeforeEachCallback;
import org.junit.jupiter.api.extension.ExtensionContext;

/**
 * A JADE main container for tests, started on first use and closed after the tests it serves, then
 * the check that it left no thread behind. Registered on a static field, one platform serves the
 * whole class and closes after it; on an instance field, each test that uses it gets its own:
 *
 * <pre>{@code
 * @RegisterExtension
 * static final JadePlatformExtension JADE = new JadePlatformExtension();
 *
 * @Test
 * void aMission() throws Exception {
 *     JADE.platform().container().acceptNewAgent("greeter", new GreeterAgent()).start();
 *     MaslMission.fromFile(Path.of("src/test/masl/greet.masl")).runOn(JADE.missionPlatform()).assertJournal("hello team\n");
 * }
 * }</pre>
 *
 * <p>The platform is {@link JadeOptions#mainContainer()}: loopback only, a free port, no HTTP
 * transport, no multicast main-detection. Closing it ({@link JadePlatform#close()}) shuts the
 * platform down through the AMS, never by {@code kill()} (which leaves the AMS's and DF's threads
 * alive) nor {@code System.exit}. Then no JADE thread may be alive, nor any other thread started
 * while the platform served that has not ended within 10 s (but the JVM's, JUnit's and the common
 * fork-join pool's, see {@link ThreadSnapshot}); otherwise the class (or the test) fails, naming each
 * such thread and the frame it is at.
 */
public final class JadePlatformExtension
        implements BeforeAllCallback, AfterAllCallback, BeforeEachCallback, AfterEachCallback {

    /** How long threads started while the platform served may take to end once it closed. */
    private final Duration threadsEndWithin;
    /** Whether one platform serves the whole class: the extension is on a static field. */
    private boolean servesClass;
    /** Who the current platform serves, as failure messages name it: the class or the test. */
    private String owner;
    private ThreadSnapshot threadsBefore;
    private JadePlatform platform;

    public JadePlatformExtension() {
        this(Duration.ofSeconds(10));
    }

    JadePlatformExtension(Duration threadsEndWithin) {
        this.threadsEndWithin = threadsEndWithin;
    }

    @Override
    public void beforeAll(ExtensionContext context) {
        servesClass = true;
        open(context);
    }

    @Override
    public void afterAll(ExtensionContext context) throws InterruptedException {
        close();
    }

    @Override
    public void beforeEach(ExtensionContext context) {
        if (!servesClass) {
            open(context);
        }
    }

    @Override
    public void afterEach(ExtensionContext context) throws InterruptedException {
        if (!servesClass) {
            close();
        }
    }

    /**
     * The platform of the class (or of the test), started by the first call.
     *
     * @throws masl.jade.platform.JadeException if JADE cannot start it; the message says why
     * @throws IllegalStateException if called outside the tests it serves
     */
    public synchronized JadePlatform platform() {
        if (owner == null) {
            throw new IllegalStateException("the JADE platform serves tests only: register "
                    + "JadePlatformExtension with @RegisterExtension and call platform() from a test or its set-up");
        }
        if (platform == null) {
            platform = JadePlatform.start(JadeOptions.mainContainer());
        }
        return platform;
    }

    /**
     * The platform of the class (or of the test) as a place to run missions under test:
     * {@code mission.runOn(JADE.missionPlatform())} runs one inside it ({@link InJade}).
     */
    public MissionPlatform missionPlatform() {
        return InJade.on(platform());
    }

    private synchronized void open(ExtensionContext context) {
        owner = context.getDisplayName();
        threadsBefore = ThreadSnapshot.take();
    }

    private synchronized void close() throws InterruptedException {
        List<String> problems = new ArrayList<>();
        RuntimeException closeFailure = null;
        String ended = platform == null ? "it ended" : "its JADE platform closed";
        if (platform != null) {
            try {
                platform.close();
            } catch (RuntimeException e) {
                closeFailure = e;
                problems.add("the JADE platform did not close: " + e.getMessage());
            }
        }
        List<Thread> left = threadsBefore.awaitStartedEnded(threadsEndWithin);
        if (!left.isEmpty()) {
            problems.add("threads it started are alive " + threadsEndWithin.toMillis() + " ms after " + ended + ": "
                    + describe(left));
        }
        List<Thread> olderJadeThreads = JadeThreads.live().stream().filter(thread -> !left.contains(thread)).toList();
        if (!olderJadeThreads.isEmpty()) {
            problems.add("JADE threads alive since before it started (left by an earlier test): "
                    + describe(olderJadeThreads));
        }
        String served = owner;
        owner = null;
        platform = null;
        if (!problems.isEmpty()) {
            throw new AssertionError(served + ": " + String.join("; ", problems), closeFailure);
        }
    }

    private static String describe(List<Thread> threads) {
        return threads.stream().map(ThreadSnapshot::describe).collect(Collectors.joining(", ", "[", "]"));
    }
}
