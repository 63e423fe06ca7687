package masl.sim.xode;

import java.util.Locale;

/**
 * Reads typed attribute values and reports missing or malformed ones. A bad value is reported
 * once and replaced by a harmless default, so reading can go on and find the file's other errors.
 */
final class Attributes {

    private final Problems problems;

    Attributes(Problems problems) {
        this.problems = problems;
    }

    /** A required finite decimal number; 0 after reporting when missing or malformed. */
    double required(XodeElement element, String name) {
        return element.attribute(name).map(v -> parse(element, name, v, 0)).orElseGet(() -> {
            problems.error(element, "missing required attribute '" + name + "'");
            return 0.0;
        });
    }

    /** An optional finite decimal number. */
    double optional(XodeElement element, String name, double fallback) {
        return element.attribute(name).map(v -> parse(element, name, v, fallback)).orElse(fallback);
    }

    /** A required number that must be strictly positive (sizes, radii, lengths). */
    double positive(XodeElement element, String name) {
        double value = required(element, name);
        if (element.attribute(name).isPresent() && isNumber(element.attribute(name).get()) && value <= 0) {
            problems.error(element, "attribute '" + name + "' must be greater than 0, found " + element.attribute(name).get());
            return 1;
        }
        return value;
    }

    /** A required non-negative integer (trimesh indices). */
    int index(XodeElement element, String name) {
        String text = element.attribute(name).orElse(null);
        if (text == null) {
            problems.error(element, "missing required attribute '" + name + "'");
            return 0;
        }
        try {
            int value = Integer.parseInt(text.trim());
            if (value >= 0) {
                return value;
            }
        } catch (NumberFormatException ignored) {
            // reported below with the offending text
        }
        problems.error(element, "attribute '" + name + "' must be a non-negative integer, found '" + text + "'");
        return 0;
    }

    /** {@code true}/{@code false}, case-insensitively. */
    boolean bool(XodeElement element, String name, boolean fallback) {
        String text = element.attribute(name).orElse(null);
        if (text == null) {
            return fallback;
        }
        String lower = text.trim().toLowerCase(Locale.ROOT);
        if (lower.equals("true") || lower.equals("false")) {
            return lower.equals("true");
        }
        problems.error(element, "attribute '" + name + "' must be true or false, found '" + text + "'");
        return fallback;
    }

    /** One of the given words, case-insensitively; returns the word as written in {@code allowed}. */
    String choice(XodeElement element, String name, String fallback, String... allowed) {
        String text = element.attribute(name).orElse(null);
        if (text == null) {
            return fallback;
        }
        for (String word : allowed) {
            if (word.equalsIgnoreCase(text.trim())) {
                return word;
            }
        }
        problems.error(element, "attribute '" + name + "' must be one of " + String.join(", ", allowed) + ", found '" + text + "'");
        return fallback;
    }

    private double parse(XodeElement element, String name, String text, double fallback) {
        if (isNumber(text)) {
            return Double.parseDouble(text.trim());
        }
        problems.error(element, "attribute '" + name + "' must be a decimal number, found '" + text + "'");
        return fallback;
    }

    /** Decimal floats only: Java's parser would also take "NaN", "Infinity" and hex floats. */
    private static boolean isNumber(String text) {
        return text.trim().matches("[+-]?(\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d+)?")
                && Double.isFinite(Double.parseDouble(text.trim()));
    }
}
