package masl.translator.diagnostics;

import java.util.Collection;
import java.util.Optional;

/**
 * "Did you mean …?" for a name that is not found: the closest of the names that would have been
 * found there, by edit distance (insertions, deletions, substitutions and swaps of two neighbours,
 * each costing one), when it is close enough to be a slip of the keyboard rather than another word.
 */
public final class Suggestions {

    private Suggestions() {
    }

    /**
     * The hint to append to a message ({@code "; did you mean `logln`?"}), or {@code ""} when no
     * candidate is close to {@code written}.
     */
    public static String hint(String written, Collection<String> candidates) {
        return closest(written, candidates).map(name -> "; did you mean `" + name + "`?").orElse("");
    }

    /**
     * The candidate nearest to {@code written}, if it is within a third of the longer of the two
     * lengths (at least one edit). Among equally near ones, one that {@code written} is a
     * subsequence of (a letter left out is the likelier slip: {@code logn} means {@code logln},
     * not {@code log}), then the first in iteration order. A candidate equal to {@code written} but
     * for case always qualifies.
     */
    public static Optional<String> closest(String written, Collection<String> candidates) {
        String best = null;
        int bestDistance = Integer.MAX_VALUE;
        for (String candidate : candidates) {
            if (candidate.equals(written)) {
                continue;
            }
            int distance = candidate.equalsIgnoreCase(written) ? 0 : distance(written, candidate);
            int allowed = Math.max(1, Math.max(written.length(), candidate.length()) / 3);
            boolean nearer = distance < bestDistance
                    || distance == bestDistance && isSubsequence(written, candidate) && !isSubsequence(written, best);
            if (distance <= allowed && nearer) {
                best = candidate;
                bestDistance = distance;
            }
        }
        return Optional.ofNullable(best);
    }

    /** Whether the letters of {@code part} stand in {@code whole} in the same order. */
    private static boolean isSubsequence(String part, String whole) {
        int next = 0;
        for (int i = 0; i < whole.length() && next < part.length(); i++) {
            if (whole.charAt(i) == part.charAt(next)) {
                next++;
            }
        }
        return next == part.length();
    }

    /** Optimal string alignment distance: Levenshtein's, plus a swap of two neighbours as one edit. */
    static int distance(String a, String b) {
        int[][] d = new int[a.length() + 1][b.length() + 1];
        for (int i = 0; i <= a.length(); i++) {
            d[i][0] = i;
        }
        for (int j = 0; j <= b.length(); j++) {
            d[0][j] = j;
        }
        for (int i = 1; i <= a.length(); i++) {
            for (int j = 1; j <= b.length(); j++) {
                int cost = a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1;
                d[i][j] = Math.min(Math.min(d[i - 1][j] + 1, d[i][j - 1] + 1), d[i - 1][j - 1] + cost);
                if (i > 1 && j > 1 && a.charAt(i - 1) == b.charAt(j - 2) && a.charAt(i - 2) == b.charAt(j - 1)) {
                    d[i][j] = Math.min(d[i][j], d[i - 2][j - 2] + 1);
                }
            }
        }
        return d[a.length()][b.length()];
    }
}
