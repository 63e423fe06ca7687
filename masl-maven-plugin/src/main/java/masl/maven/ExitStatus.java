package masl.maven;

/** What an exit status of the {@code masl} command means (its README: "Exit status"; the Gradle plug-in's {@code MaslExit} says the same). */
final class ExitStatus {

    static final int MISSION_FAILED = 2;

    private ExitStatus() {
    }

    static String meaning(int status) {
        return switch (status) {
            case 1 -> "errors in the program or its descriptors, or an agent class that cannot be made";
            case MISSION_FAILED -> "the mission failed, deadlocked, timed out or was stopped, or its journal or trace could not be written";
            case 64 -> "masl was called wrongly";
            case 70 -> "an internal error of masl";
            case 71 -> "out of memory before the mission ran: the program is too large for masl's heap";
            case 74 -> "an output could not be written";
            case 130 -> "stopped by Ctrl-C";
            case 143 -> "stopped by SIGTERM";
            default -> "a status masl does not give";
        };
    }
}
