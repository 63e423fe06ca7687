package masl.gradle;

import java.io.OutputStream;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import masl.translator.diagnostics.MaslErrorLines;
import org.gradle.api.GradleException;
import org.gradle.api.tasks.JavaExec;

/**
 * The message of a failed {@code maslRun} or {@code maslContainer}: which mission or container, why,
 * and masl's exit status with what it means. Gradle 4.4's {@code JavaExec} gives no exit status but in the message of its failure ("…
 * finished with non-zero exit value 2"), which every Gradle since words the same way.
 */
final class MaslExit {

    private static final Pattern EXIT_VALUE = Pattern.compile("exit value (\\d+)");

    private MaslExit() {
    }

    /**
     * Runs {@code exec}, {@code task}'s own action, failing with what {@link #describe} says if masl
     * fails: masl's standard error passes on to the task's as it comes, read for why.
     */
    static void reporting(JavaExec task, Runnable exec, String what, String name) {
        OutputStream errors = task.getErrorOutput();
        MaslErrorLines report = new MaslErrorLines(errors);
        task.setErrorOutput(report);
        try {
            exec.run();
        } catch (RuntimeException failed) {
            throw new GradleException(describe(what, name, failed, report.why()), failed);
        } finally {
            task.setErrorOutput(errors);
        }
    }

    static String describe(String mission, RuntimeException failure, String why) {
        return describe("mission", mission, failure, why);
    }

    /** {@code what} is {@code mission} or {@code container}, {@code name} its name. */
    static String describe(String what, String name, RuntimeException failure, String why) {
        StringBuilder message = new StringBuilder(what).append(' ').append(name).append(" failed");
        if (!why.isEmpty()) {
            message.append(": ").append(why);
        }
        Integer status = status(failure);
        message.append(status == null ? " (" + failure.getMessage() + ")" : " (masl exit status " + status + ": " + meaning(status) + ")");
        return message.append("; masl's report is above").toString();
    }

    private static Integer status(RuntimeException failure) {
        for (Throwable cause = failure; cause != null; cause = cause.getCause()) {
            Matcher value = cause.getMessage() == null ? null : EXIT_VALUE.matcher(cause.getMessage());
            if (value != null && value.find()) {
                return Integer.valueOf(value.group(1));
            }
        }
        return null;
    }

    /** The statuses of the {@code masl} command, as its README lists them (the Maven plug-in's {@code ExitStatus} says the same). */
    static String meaning(int status) {
        return switch (status) {
            case 1 -> "errors in the program or its descriptors, or an agent class that cannot be made";
            case 2 -> "the mission failed, deadlocked, timed out or was stopped, or its journal or trace could not be written";
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
