package masl.runtime.scheduling;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.regex.Pattern;

/**
 * How to run a mission again under the seed of a run ({@link SeededScheduler}), in the words of the
 * tool that ran it: the {@code masl} command, or a build's task ({@code gradle maslRun}, {@code mvn
 * masl:run}). A failure's replay hint is this text, so that it names a command that works where it
 * is shown; the command, {@code masl-testing} and the build plug-ins share it.
 *
 * <p>A build plug-in that starts {@code masl run} in a JVM of its own hands its form to the command
 * as the system property {@value #PROPERTY}: a template, with {@value #SEED} where the seed goes.
 */
public final class ReplayCommand {

    /** The system property through which a build tells {@code masl run} how it runs a mission again. */
    public static final String PROPERTY = "masl.replay";
    /** Where a template takes the seed. */
    public static final String SEED = "{seed}";

    /** Words a POSIX shell takes as they are; any other is quoted. */
    private static final Pattern PLAIN_WORD = Pattern.compile("[A-Za-z0-9_./:=@%+,-]+");

    private final String template;

    private ReplayCommand(String template) {
        this.template = template;
    }

    /**
     * A command given as a template.
     *
     * @throws IllegalArgumentException if it has no {@value #SEED}
     */
    public static ReplayCommand of(String template) {
        if (!template.contains(SEED)) {
            throw new IllegalArgumentException("a replay command takes the seed where it says " + SEED + ": " + template);
        }
        return new ReplayCommand(template);
    }

    /** The form a build plug-in handed the running JVM ({@value #PROPERTY}), if any. */
    public static Optional<ReplayCommand> fromSystemProperty() {
        String template = System.getProperty(PROPERTY);
        return template == null || template.isBlank() ? Optional.empty() : Optional.of(of(template));
    }

    /**
     * {@code masl run PROGRAM OPTIONS… --seed N}: {@code options} are the command's options that make
     * the run what it was ({@code --agent-path robots}, {@code --call-timeout 500}).
     */
    public static ReplayCommand masl(String program, List<String> options) {
        List<String> words = new ArrayList<>(List.of("masl", "run", program));
        words.addAll(options);
        words.add("--seed");
        return new ReplayCommand(shellWords(words) + " " + SEED);
    }

    /**
     * {@code gradle maslRun -Pmission=NAME -PNAME=VALUE… -Pseed=N}: {@code properties} ({@code
     * callTimeout=500}) are the plug-in's project properties that make the run what it was.
     */
    public static ReplayCommand gradle(String mission, List<String> properties) {
        return build(List.of("gradle", "maslRun"), "-P", mission, properties);
    }

    /** {@code mvn masl:run -Dmission=NAME -DNAME=VALUE… -Dseed=N}, as {@link #gradle} for Maven's plug-in. */
    public static ReplayCommand maven(String mission, List<String> properties) {
        return build(List.of("mvn", "masl:run"), "-D", mission, properties);
    }

    private static ReplayCommand build(List<String> command, String prefix, String mission, List<String> properties) {
        List<String> words = new ArrayList<>(command);
        words.add(prefix + "mission=" + mission);
        properties.forEach(property -> words.add(prefix + property));
        return new ReplayCommand(shellWords(words) + " " + prefix + "seed=" + SEED);
    }

    /** The template, as {@value #PROPERTY} carries it. */
    public String template() {
        return template;
    }

    /** The command that runs the mission again under {@code seed}. */
    public String forSeed(long seed) {
        return template.replace(SEED, Long.toString(seed));
    }

    private static String shellWords(List<String> words) {
        List<String> quoted = new ArrayList<>();
        for (String word : words) {
            quoted.add(PLAIN_WORD.matcher(word).matches() ? word : "'" + word.replace("'", "'\\''") + "'");
        }
        return String.join(" ", quoted);
    }

    @Override
    public String toString() {
        return template;
    }
}
