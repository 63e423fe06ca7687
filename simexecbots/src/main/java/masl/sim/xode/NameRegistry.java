package masl.sim.xode;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * Gives named elements their prefixed names and remembers who uses which name, so that clashes
 * with the target world are errors and duplicates inside the document can be judged once links
 * are known (xode.md §10.15).
 */
final class NameRegistry {

    private final Problems problems;
    private final String prefix;
    private final Set<String> takenNames;
    private final Map<String, List<XodeElement>> users = new LinkedHashMap<>();

    /** @param takenNames prefixed names already used in the target world */
    NameRegistry(Problems problems, String prefix, Set<String> takenNames) {
        this.problems = problems;
        this.prefix = prefix;
        this.takenNames = takenNames;
    }

    /** The element's prefixed name, or null when it has no {@code name}. */
    String register(XodeElement element) {
        String raw = element.attribute("name").orElse(null);
        if (raw == null) {
            return null;
        }
        String prefixed = prefix + raw;
        if (takenNames.contains(prefixed)) {
            problems.error(element, "the name '" + prefixed + "' is already used in the target world; load this file with another prefix");
        }
        users.computeIfAbsent(prefixed, n -> new ArrayList<>()).add(element);
        return prefixed;
    }

    /** The name as written in the file, for messages. */
    String unprefixed(String prefixed) {
        return prefixed.substring(prefix.length());
    }

    /** Reports every reuse of a name: an error when a joint links to that name, else a warning. */
    void reportDuplicates(Set<String> linkTargets) {
        users.forEach((name, elements) -> {
            for (XodeElement reuse : elements.subList(1, elements.size())) {
                String message = "the name '" + unprefixed(name) + "' is already used at " + elements.get(0).location();
                if (linkTargets.contains(name)) {
                    problems.error(reuse, message + ", and a joint links to it");
                } else {
                    problems.warning(reuse, message);
                }
            }
        });
    }
}
