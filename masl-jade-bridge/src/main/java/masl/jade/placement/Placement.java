package masl.jade.placement;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;
import masl.runtime.diagnostic.Diagnostic;

/**
 * Where each MASL agent's body lives ({@code masl run --place}): {@code w1=c2,w3=c2} on the command
 * line, or a file of such pairs, one per line ({@code #} starts a comment). Agents not named stay
 * in the coordinator's container. A mistake is reported with its position
 * ({@code places.txt:3:4: error: …}, or {@code --place w1=c2,w2: column 7: error: …}).
 */
public final class Placement {

    private static final Pattern NAME = Pattern.compile("[A-Za-z_$][A-Za-z0-9_$]*");
    private static final Pattern CONTAINER = Pattern.compile("[A-Za-z0-9_.-]+");

    private Placement() {
    }

    /** A placement given as {@code a=c,b=c}, or, if the text holds no {@code =}, the name of a placement file. */
    public static Map<String, String> parse(String option) {
        if (option.contains("=")) {
            Map<String, String> placement = new LinkedHashMap<>();
            int column = 1;
            for (String pair : option.split(",", -1)) {
                add(placement, pair, "--place " + option, 0, column);
                column += pair.length() + 1;
            }
            return placement;
        }
        return read(Path.of(option));
    }

    /** @throws IllegalArgumentException positioned in the file, or if it cannot be read */
    public static Map<String, String> read(Path file) {
        List<String> lines;
        try {
            lines = Files.readAllLines(file);
        } catch (IOException | UncheckedIOException e) {
            throw new IllegalArgumentException("cannot read placement file " + file + ": " + e.getMessage());
        }
        Map<String, String> placement = new LinkedHashMap<>();
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i);
            int comment = line.indexOf('#');
            String content = comment < 0 ? line : line.substring(0, comment);
            if (!content.isBlank()) {
                add(placement, content, file.toString(), i + 1, 1);
            }
        }
        return placement;
    }

    /** @param where the file, or the option and its value ({@code line} 0: a value has columns only) */
    private static void add(Map<String, String> placement, String pair, String where, int line, int column) {
        int leading = pair.length() - pair.stripLeading().length();
        String text = pair.strip();
        int equals = text.indexOf('=');
        if (equals < 0) {
            throw error(where, line, column + leading, "expected AGENT=CONTAINER, got '" + text + "'");
        }
        String agent = text.substring(0, equals).strip();
        String container = text.substring(equals + 1).strip();
        if (!NAME.matcher(agent).matches()) {
            throw error(where, line, column + leading, "'" + agent + "' is not an agent name");
        }
        if (!CONTAINER.matcher(container).matches()) {
            throw error(where, line, column + leading + equals + 1, "'" + container + "' is not a container name"
                    + " (letters, digits, '_', '.', '-')");
        }
        if (placement.putIfAbsent(agent, container) != null) {
            throw error(where, line, column + leading, agent + " is placed twice");
        }
    }

    private static IllegalArgumentException error(String where, int line, int column, String message) {
        return new IllegalArgumentException(Diagnostic.error(where, line, column, message).headline());
    }
}
