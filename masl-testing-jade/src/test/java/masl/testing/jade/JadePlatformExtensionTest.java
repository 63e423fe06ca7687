package masl.testing.jade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Proxy;
import java.nio.file.Files;
import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import masl.jade.platform.JadeOptions;
import masl.jade.platform.JadePlatform;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.ExtensionContext;

/**
 * The extension's life cycle as JUnit drives it (its callbacks called here in JUnit's order), and
 * the failures it reports: the threads a class or a test left, and JADE threads an earlier test left.
 */
@Timeout(120)
class JadePlatformExtensionTest {

    @Test
    void onAStaticFieldOnePlatformServesEveryTestOfTheClassAndClosesAfterIt() throws Exception {
        JadePlatformExtension extension = new JadePlatformExtension();
        extension.beforeAll(context("SomeClassTest"));
        extension.beforeEach(context("first()"));
        JadePlatform platform = extension.platform();
        assertEquals("127.0.0.1", platform.host());
        extension.afterEach(context("first()"));
        extension.beforeEach(context("second()"));
        assertSame(platform, extension.platform());
        extension.afterEach(context("second()"));
        assertTrue(Files.exists(platform.fileDir()), "still open between the tests of the class");
        extension.afterAll(context("SomeClassTest"));
        assertFalse(Files.exists(platform.fileDir()), "closed after the class");
    }

    @Test
    void onAnInstanceFieldEachTestHasItsOwnPlatformClosedAfterIt() throws Exception {
        JadePlatformExtension extension = new JadePlatformExtension();
        extension.beforeEach(context("first()"));
        JadePlatform platform = extension.platform();
        extension.afterEach(context("first()"));
        assertFalse(Files.exists(platform.fileDir()), "closed after the test");
        IllegalStateException outside = assertThrows(IllegalStateException.class, extension::platform);
        assertEquals("the JADE platform serves tests only: register JadePlatformExtension with @RegisterExtension "
                + "and call platform() from a test or its set-up", outside.getMessage());
    }

    @Test
    void aThreadLeftByTheTestsFailsTheClassNamingIt() throws Exception {
        JadePlatformExtension extension = new JadePlatformExtension(Duration.ofMillis(100));
        CountDownLatch release = new CountDownLatch(1);
        Thread leaked = new Thread(() -> awaitQuietly(release), "leaked-by-a-test");
        extension.beforeAll(context("LeakyTest"));
        leaked.start();
        try {
            AssertionError failure = assertThrows(AssertionError.class, () -> extension.afterAll(context("LeakyTest")));
            assertTrue(failure.getMessage().startsWith(
                    "LeakyTest: threads it started are alive 100 ms after it ended: [leaked-by-a-test at "),
                    failure.getMessage());
            assertTrue(failure.getMessage().contains("masl.testing.jade.JadePlatformExtensionTest.awaitQuietly("),
                    "the frame of the test's code the thread waits in: " + failure.getMessage());
        } finally {
            release.countDown();
            leaked.join();
        }
    }

    @Test
    void jadeThreadsOfAnEarlierPlatformAreReportedAsAnEarlierTestsLeftovers() throws Exception {
        JadePlatformExtension extension = new JadePlatformExtension(Duration.ZERO);
        try (JadePlatform earlier = JadePlatform.start(JadeOptions.mainContainer())) {
            extension.beforeEach(context("later()"));
            AssertionError failure = assertThrows(AssertionError.class, () -> extension.afterEach(context("later()")));
            assertTrue(failure.getMessage().contains(
                    "JADE threads alive since before it started (left by an earlier test): ["), failure.getMessage());
            assertTrue(failure.getMessage().startsWith("later(): "), failure.getMessage());
        }
    }

    private static void awaitQuietly(CountDownLatch latch) {
        try {
            latch.await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** A context as JUnit hands the extension one, for a class or a test of that display name. */
    private static ExtensionContext context(String displayName) {
        return (ExtensionContext) Proxy.newProxyInstance(ExtensionContext.class.getClassLoader(),
                new Class<?>[] {ExtensionContext.class}, (proxy, method, args) -> {
                    if (method.getName().equals("getDisplayName")) {
                        return displayName;
                    }
                    throw new UnsupportedOperationException(method.getName());
                });
    }
}
