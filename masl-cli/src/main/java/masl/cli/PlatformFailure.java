package masl.cli;

/**
 * A platform that could not run the mission (JADE: cannot join, a container cannot host an agent),
 * in words meant for the user as they are: reported in one line. Its own type, so that reporting it
 * loads no class of a platform a run does not use (the in-process run has no JADE on its class path).
 */
final class PlatformFailure extends RuntimeException {
    private static final long serialVersionUID = 1L;

    PlatformFailure(String message) {
        super(message);
    }
}
