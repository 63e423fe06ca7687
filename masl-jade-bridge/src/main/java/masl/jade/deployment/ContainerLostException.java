package masl.jade.deployment;

/**
 * The container running a deployed agent's program is gone (its JVM ended or died): the agent's
 * step, or a call it made, cannot go on; the agent fails with this as its cause, naming the container.
 */
public final class ContainerLostException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public ContainerLostException(String message) {
        super(message);
    }
}
