package masl.jade.platform;

import java.util.Objects;
import java.util.logging.Level;

/**
 * How a {@link JadePlatform} is started: a main container of a new platform on loopback (the
 * default), or a peripheral container joining the main container at {@code mainHost:mainPort}.
 * Immutable; the {@code with…} methods return modified copies.
 *
 * <pre>{@code
 * JadeOptions.mainContainer()                   // new platform, free loopback port
 * JadeOptions.mainContainer().withPort(1099)    // new platform on a given port
 * JadeOptions.join("127.0.0.1", 1099)           // a container of a running platform
 * }</pre>
 */
public final class JadeOptions {

    /** The address every container binds to unless told otherwise: loopback (JADE needs the literal). */
    public static final String LOOPBACK = "127.0.0.1";

    private final boolean join;
    private final String mainHost;
    private final int mainPort;
    private final int localPort;
    private final String localHost;
    private final boolean httpTransport;
    private final String containerName;
    private final Level jadeLogLevel;

    private JadeOptions(boolean join, String mainHost, int mainPort, int localPort, String localHost,
            boolean httpTransport, String containerName, Level jadeLogLevel) {
        this.join = join;
        this.mainHost = mainHost;
        this.mainPort = checkPort(mainPort);
        this.localPort = checkPort(localPort);
        this.localHost = Objects.requireNonNull(localHost, "localHost");
        this.httpTransport = httpTransport;
        this.containerName = containerName;
        this.jadeLogLevel = Objects.requireNonNull(jadeLogLevel, "jadeLogLevel");
    }

    /** A new platform: its main container on loopback, on a free port, no GUI, no HTTP transport. */
    public static JadeOptions mainContainer() {
        return new JadeOptions(false, LOOPBACK, 0, 0, LOOPBACK, false, null, Level.WARNING);
    }

    /** A peripheral container joining the platform whose main container listens at {@code host:port}. */
    public static JadeOptions join(String host, int port) {
        if (port <= 0) {
            throw new IllegalArgumentException("main port: " + port);
        }
        return new JadeOptions(true, Objects.requireNonNull(host, "host"), port, 0, LOOPBACK, false, null,
                Level.WARNING);
    }

    /**
     * The port this container listens on for intra-platform commands; 0 (the default) picks a free
     * one. For a main container this is the port other containers join.
     */
    public JadeOptions withPort(int port) {
        return new JadeOptions(join, mainHost, mainPort, port, localHost, httpTransport, containerName,
                jadeLogLevel);
    }

    /** The address this container binds to and advertises: loopback unless set. */
    public JadeOptions withLocalHost(String host) {
        return new JadeOptions(join, join ? mainHost : host, mainPort, localPort, host, httpTransport,
                containerName, jadeLogLevel);
    }

    /** Starts JADE's HTTP message transport (for agents of other platforms); off by default. */
    public JadeOptions withHttpTransport(boolean on) {
        return new JadeOptions(join, mainHost, mainPort, localPort, localHost, on, containerName, jadeLogLevel);
    }

    /** The container's name; JADE chooses one ({@code Main-Container}, {@code Container-1}) unless set. */
    public JadeOptions withContainerName(String name) {
        return new JadeOptions(join, mainHost, mainPort, localPort, localHost, httpTransport, name, jadeLogLevel);
    }

    /**
     * The least severe level of JADE's own log records that are printed (through
     * {@code java.util.logging}, on standard error by default): {@link Level#WARNING} unless set,
     * which keeps JADE's start-up banner and INFO lines off standard error.
     */
    public JadeOptions withJadeLogLevel(Level level) {
        return new JadeOptions(join, mainHost, mainPort, localPort, localHost, httpTransport, containerName, level);
    }

    public boolean joins() {
        return join;
    }

    /** The main container's host: this container's own address when it is the main container. */
    public String mainHost() {
        return mainHost;
    }

    /** The main container's port to join; 0 for a main container (see {@link #localPort()}). */
    public int mainPort() {
        return mainPort;
    }

    /** 0 means "a free port". */
    public int localPort() {
        return localPort;
    }

    public String localHost() {
        return localHost;
    }

    public boolean httpTransport() {
        return httpTransport;
    }

    /** Null when JADE chooses. */
    public String containerName() {
        return containerName;
    }

    public Level jadeLogLevel() {
        return jadeLogLevel;
    }

    private static int checkPort(int port) {
        if (port < 0 || port > 65535) {
            throw new IllegalArgumentException("port: " + port);
        }
        return port;
    }

    @Override
    public String toString() {
        return join ? "join " + mainHost + ":" + mainPort : "main container on " + localHost + ":"
                + (localPort == 0 ? "free port" : localPort);
    }
}
