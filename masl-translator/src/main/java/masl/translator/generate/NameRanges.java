package masl.translator.generate;

import java.util.ArrayList;
import java.util.List;
import masl.translator.analysis.AgentDecl;

/**
 * The names of a run of agents as the mission class lists them: a stretch of three or more names
 * that count up by one ({@code a3, a4, a5, a6}) as one range {@code a3..a6}. A mission of 100,000
 * agents then lists them in a few characters, and javac does not read a table of every name.
 * A range's numbers are decimal without leading zeros, so that counting reproduces each name.
 */
final class NameRanges {

    private static final int SHORTEST_RANGE = 3;
    /** Digits a long counts through without overflow. */
    private static final int MOST_DIGITS = 18;

    private NameRanges() {
    }

    static List<String> of(List<AgentDecl> agents) {
        List<String> names = new ArrayList<>();
        int i = 0;
        while (i < agents.size()) {
            String first = agents.get(i).name();
            int end = i + 1;
            int prefix = prefixLength(first);
            if (prefix >= 0) {
                long next = Long.parseLong(first.substring(prefix)) + 1;
                while (end < agents.size() && agents.get(end).name().equals(first.substring(0, prefix) + next)) {
                    end++;
                    next++;
                }
            }
            if (end - i >= SHORTEST_RANGE) {
                names.add(first + ".." + agents.get(end - 1).name());
                i = end;
            } else {
                names.add(first);
                i++;
            }
        }
        return names;
    }

    /** Where the number ending {@code name} starts, or -1 if it ends in none that a range can count from. */
    private static int prefixLength(String name) {
        int prefix = name.length();
        while (prefix > 0 && name.charAt(prefix - 1) >= '0' && name.charAt(prefix - 1) <= '9') {
            prefix--;
        }
        int digits = name.length() - prefix;
        boolean leadingZero = digits > 1 && name.charAt(prefix) == '0';
        return digits == 0 || prefix == 0 || leadingZero || digits > MOST_DIGITS ? -1 : prefix;
    }
}
