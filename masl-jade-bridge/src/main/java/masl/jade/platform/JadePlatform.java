package masl.jade.platform;

import jade.core.Agent;
import jade.core.Profile;
import jade.core.ProfileImpl;
import jade.core.Runtime;
import jade.domain.JADEAgentManagement.ShutdownPlatform;
import jade.wrapper.AgentContainer;
import jade.wrapper.ControllerException;
import jade.wrapper.StaleProxyException;
import java.io.File;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Stream;

/**
 * One JADE container run by this JVM: the main container of a new platform, or a peripheral
 * container joining a running one ({@link JadeOptions}). It binds to loopback unless told
 * otherwise, starts no GUI, no HTTP transport unless asked and no multicast main-detection, prints
 * JADE's log records from WARNING up as single lines (see {@link JadeLog}), and writes JADE's
 * files ({@code APDescription.txt}) into a temporary folder instead of the working directory.
 *
 * <p>{@link #close()} ends the container and leaves no JADE thread behind once the last container
 * of the JVM has ended. Closing a main container shuts the whole platform down (every container of
 * it, in every JVM) through the AMS, the only way that also ends the AMS's and DF's threads:
 * killing the main container leaves them alive for good. JADE refuses to end a container younger
 * than 3 s and waits for that age first, so a platform lives at least 3 s.
 *
 * <p>JADE's runtime is one per JVM: starts and closes are serialised. Thread-safe.
 */
public final class JadePlatform implements AutoCloseable {

    /** How long closing waits for the platform to end and for JADE's threads to finish. */
    public static final Duration SHUTDOWN_TIMEOUT = Duration.ofSeconds(30);
    /** How long {@link #leave()} waits for JADE's threads to end before it leaves them. */
    private static final Duration LEAVE_THREADS_WAIT = Duration.ofSeconds(1);
    /** How long a container its platform may be ending has for that end before it ends itself ({@link #endedByItsPlatform}). */
    private static final Duration EXIT_GRACE = Duration.ofSeconds(5);
    /** How long the AMS has to end the platform before it is asked again. */
    private static final Duration AMS_RETRY_AFTER = Duration.ofSeconds(10);

    private static final Object LIFECYCLE = new Object();
    /** Containers started by this class and not closed yet: the last close waits for JADE's threads. */
    private static final AtomicInteger OPEN = new AtomicInteger();
    private static final int PORT_ATTEMPTS = 5;
    private static final AtomicInteger SHUTDOWN_AGENTS = new AtomicInteger();

    private final JadeOptions options;
    private final AgentContainer container;
    private final int port;
    private final String httpAddress;
    private final Path fileDir;
    private final CountDownLatch terminated = new CountDownLatch(1);
    private boolean closed;
    /** Whether the platform's shutdown may be ending this container, which then has a grace to end before it is ended here. */
    private volatile boolean endedByItsPlatform;

    private JadePlatform(JadeOptions options, AgentContainer container, int port, String httpAddress,
            Path fileDir) {
        this.options = options;
        this.container = container;
        this.port = port;
        this.httpAddress = httpAddress;
        this.fileDir = fileDir;
    }

    /**
     * Starts a main container or joins a platform, as {@code options} say.
     *
     * @throws JadeException when JADE cannot start the container (port taken, no main container at
     *                       the address to join, …); the message says which
     */
    public static JadePlatform start(JadeOptions options) {
        synchronized (LIFECYCLE) {
            JadeLog.setLevel(options.jadeLogLevel());
            Runtime.instance().setCloseVM(false);
            Path fileDir = createFileDir();
            try {
                JadePlatform platform = startContainer(options, fileDir);
                OPEN.incrementAndGet();
                Runtime.instance().invokeOnTermination(platform.terminated::countDown);
                return platform;
            } catch (RuntimeException e) {
                deleteRecursively(fileDir);
                throw e;
            }
        }
    }

    private static JadePlatform startContainer(JadeOptions options, Path fileDir) {
        boolean choosePort = options.localPort() == 0;
        // Checked first because JADE prints a stack trace for this common mistake. (Whether a main
        // container listens is not: JADE reports any connection that sends no packet as an error.)
        if (!choosePort && !isFree(options.localHost(), options.localPort())) {
            throw cannotStart(options, options.localPort());
        }
        for (int attempt = 1; ; attempt++) {
            int port = choosePort ? freePort(options.localHost()) : options.localPort();
            String httpAddress = options.httpTransport()
                    ? "http://" + options.localHost() + ":" + freePort(options.localHost()) + "/acc"
                    : null;
            Profile profile = profile(options, port, httpAddress, fileDir);
            // A failed join is reported by cannotStart in one line: JADE's own report is stack traces.
            AgentContainer container = options.joins()
                    ? JadeLog.silenced(() -> Runtime.instance().createAgentContainer(profile))
                    : Runtime.instance().createMainContainer(profile);
            if (container != null) {
                return new JadePlatform(options, container, port, httpAddress, fileDir);
            }
            // JADE logs the reason and returns null; a port taken meanwhile is worth another try.
            if (options.joins() || !choosePort || attempt == PORT_ATTEMPTS) {
                throw cannotStart(options, port);
            }
        }
    }

    private static JadeException cannotStart(JadeOptions options, int port) {
        return new JadeException(options.joins()
                ? "cannot join the JADE platform at " + options.mainHost() + ":" + options.mainPort()
                        + " (is its main container running?)"
                : "cannot start a JADE main container on " + options.localHost() + ":" + port
                        + " (is the port free?)");
    }

    private static Profile profile(JadeOptions options, int port, String httpAddress, Path fileDir) {
        ProfileImpl profile = new ProfileImpl(false);
        profile.setParameter(Profile.MAIN, Boolean.toString(!options.joins()));
        profile.setParameter(Profile.LOCAL_HOST, options.localHost());
        profile.setParameter(Profile.LOCAL_PORT, Integer.toString(port));
        if (options.joins()) {
            profile.setParameter(Profile.MAIN_HOST, options.mainHost());
            profile.setParameter(Profile.MAIN_PORT, Integer.toString(options.mainPort()));
        }
        if (isLoopback(options.localHost())) {
            profile.setParameter("jade_imtp_leap_JICP_JICPServer_acceptlocalhostonly", "true");
        }
        if (httpAddress != null) {
            profile.setParameter(Profile.MTPS, "jade.mtp.http.MessageTransportProtocol(" + httpAddress + ")");
        } else {
            profile.setParameter(Profile.NO_MTP, "true");
        }
        profile.setParameter(Profile.DETECT_MAIN, "false");
        profile.setParameter(Profile.GUI, "false");
        profile.setParameter(Profile.FILE_DIR, fileDir.toString() + File.separator);
        if (options.containerName() != null) {
            profile.setParameter(Profile.CONTAINER_NAME, options.containerName());
        }
        // After a container ends JADE interrupts its agents' threads once this delay (5 s by
        // default) has passed, and keeps a thread alive until then.
        profile.setParameter("jade_core_FullResourceManager_threadgroupinterrupttimeout", "100");
        return profile;
    }

    /** The container, to create agents in. */
    public AgentContainer container() {
        return container;
    }

    /** Whether this is the main container of the platform it started. */
    public boolean isMain() {
        return !options.joins();
    }

    /** The address this container listens on. */
    public String host() {
        return options.localHost();
    }

    /** The port this container listens on: for a main container, the port other containers join. */
    public int port() {
        return port;
    }

    /** The address of the platform's main container: where containers join it. */
    public String mainHost() {
        return isMain() ? host() : options.mainHost();
    }

    /** The port of the platform's main container: where containers join it. */
    public int mainPort() {
        return isMain() ? port : options.mainPort();
    }

    /** The address of the HTTP transport ({@code http://127.0.0.1:PORT/acc}) if it was asked for. */
    public Optional<String> httpAddress() {
        return Optional.ofNullable(httpAddress);
    }

    /** The platform's name, as in agents' global names ({@code name@platform}). */
    public String platformName() {
        return container.getPlatformName();
    }

    /** The container's name ({@code Main-Container}, {@code Container-1}, …). */
    public String containerName() {
        try {
            return container.getContainerName();
        } catch (ControllerException e) {
            throw new JadeException("container ended", e);
        }
    }

    /** The folder JADE writes its files into (deleted by {@link #close()}). */
    public Path fileDir() {
        return fileDir;
    }

    /**
     * Ends this container (a main container: the whole platform) and, when no other container
     * started by this class is open in the JVM, waits until no JADE thread is left. Idempotent.
     *
     * @throws JadeException if the platform or JADE's threads did not end within
     *                       {@link #SHUTDOWN_TIMEOUT}
     */
    @Override
    public void close() {
        end(SHUTDOWN_TIMEOUT, true);
    }

    /**
     * Ends this container as {@link #close()} does, but waits for JADE's threads to end for
     * {@link #LEAVE_THREADS_WAIT} only, and leaves those still there: for a JVM that joins the next
     * platform at once (a container serving one mission after another). JADE 4.3 keeps its message
     * delivery threads, and gives them to the JVM's next container, once its platform's shutdown
     * removed a container that was never placed (seen every time in a serving container, not
     * explained); waiting 30 s for them would only delay every later mission.
     *
     * @throws JadeException if the container did not end within {@link #SHUTDOWN_TIMEOUT}
     */
    public void leave() {
        end(LEAVE_THREADS_WAIT, false);
    }

    /**
     * Says that this container, which joined a platform, may be being ended by that platform's
     * shutdown (JADE deleted one of its agents): {@link #close()} and {@link #leave()} then wait up to
     * {@link #EXIT_GRACE} for that end, and end the container themselves only if it has not come (an
     * agent deleted alone). JADE 4.3 does not survive a container ended twice at once: the main
     * container's order to exit and the container's own shutdown both run, JADE fails serving the
     * order ("Error serving H-Command jade.core.management.AgentManagement/8"), and every later
     * container of the JVM fails to join (seen in a serving container whose mission placed nothing on
     * it: it learns of the mission's end from the shutdown alone).
     */
    public void endedByItsPlatform() {
        endedByItsPlatform = true;
    }

    private void end(Duration threadsWithin, boolean threadsMustEnd) {
        synchronized (LIFECYCLE) {
            if (closed) {
                return;
            }
            closed = true;
            boolean last = OPEN.decrementAndGet() == 0;
            try {
                if (isMain()) {
                    shutDownPlatform();
                } else if (!endedByItsPlatform || !terminated.await(EXIT_GRACE.toNanos(), TimeUnit.NANOSECONDS)) {
                    killContainer();
                }
                if (last) {
                    List<Thread> left = JadeThreads.awaitNone(threadsWithin);
                    if (!left.isEmpty() && threadsMustEnd) {
                        throw new JadeException("JADE threads still alive after shutdown: " + left);
                    }
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new JadeException("interrupted while JADE shut down", e);
            } finally {
                deleteRecursively(fileDir);
            }
        }
    }

    /**
     * Asks the AMS to shut the platform down, and waits until the JVM's containers have ended; asks
     * again every {@link #AMS_RETRY_AFTER} until {@link #SHUTDOWN_TIMEOUT}.
     *
     * <p>Asking again, never ending the main container here: JADE 4.3's AMS sometimes fails to end
     * its own container (it logs "Cannot kill container Main-Container: Unreachable", a row of its
     * agent table read while an agent was being removed) and never retries by itself, while a main
     * container killed from outside leaves the AMS's and DF's threads alive and JADE's count of the
     * JVM's containers wrong, so that every later platform of the JVM seems ended before it is.
     */
    private void shutDownPlatform() throws InterruptedException {
        long deadline = System.nanoTime() + SHUTDOWN_TIMEOUT.toNanos();
        while (true) {
            if (!requestShutdown()) {
                return;
            }
            long left = deadline - System.nanoTime();
            if (terminated.await(Math.min(left, AMS_RETRY_AFTER.toNanos()), TimeUnit.NANOSECONDS)) {
                return;
            }
            if (System.nanoTime() - deadline >= 0) {
                throw new JadeException("the JADE platform did not shut down within " + SHUTDOWN_TIMEOUT);
            }
        }
    }

    /** Starts an agent that asks the AMS to shut the platform down; false if the container has ended. */
    private boolean requestShutdown() {
        try {
            container.acceptNewAgent("masl-shutdown-" + SHUTDOWN_AGENTS.incrementAndGet(), new ShutdownRequester())
                    .start();
            return true;
        } catch (StaleProxyException alreadyEnded) {
            return false;
        }
    }

    private void killContainer() {
        try {
            container.kill();
        } catch (StaleProxyException alreadyEnded) {
            // The platform's shutdown ended this container already.
        }
    }

    /** Sends the AMS the request to shut the platform down, once, as JADE's tools do. */
    private static final class ShutdownRequester extends Agent {
        private static final long serialVersionUID = 1L;

        @Override
        protected void setup() {
            send(AmsRequests.request(this, new ShutdownPlatform()));
        }
    }

    private static int freePort(String host) {
        try (ServerSocket socket = new ServerSocket(0, 1, InetAddress.getByName(host))) {
            return socket.getLocalPort();
        } catch (IOException e) {
            throw new JadeException("no free port on " + host + ": " + e.getMessage(), e);
        }
    }

    private static boolean isFree(String host, int port) {
        try (ServerSocket socket = new ServerSocket(port, 1, InetAddress.getByName(host))) {
            return true;
        } catch (IOException e) {
            return false;
        }
    }

    private static boolean isLoopback(String host) {
        try {
            return InetAddress.getByName(host).isLoopbackAddress();
        } catch (IOException e) {
            return false;
        }
    }

    private static Path createFileDir() {
        try {
            return Files.createTempDirectory("masl-jade-");
        } catch (IOException e) {
            throw new UncheckedIOException("cannot create a folder for JADE's files", e);
        }
    }

    private static void deleteRecursively(Path dir) {
        try (Stream<Path> paths = Files.walk(dir)) {
            for (Path path : paths.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(path);
            }
        } catch (IOException e) {
            // A leftover temporary folder is harmless; failing the shutdown for it would not be.
        }
    }

    @Override
    public String toString() {
        return "JADE " + (isMain() ? "main container" : "container") + " on " + host() + ":" + port;
    }
}
