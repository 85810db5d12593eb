package org.miron.bt.util;

import java.util.Collection;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;

/**
 * "Did you mean" candidates: the names closest to a misspelt one by edit distance. Used by the
 * linking diagnostics of the BT and the RoQME/MIRoN languages to fill a quick fix's issue data.
 */
public final class Suggestions {
    /** More than three choices is a list to read, not a suggestion. */
    public static final int MAX = 3;

    private Suggestions() {
    }

    /**
     * The at most {@link #MAX} candidates nearest to {@code wanted}, nearest first, that differ from
     * it by at most a third of the length of its last segment (after the last '.' or ':'; at least
     * one edit, at most three): a short name with many edits is another name, not a typo, and a
     * qualifier does not make a name longer. Case differences count as half an edit.
     */
    public static List<String> closest(String wanted, Collection<String> candidates) {
        if (wanted == null || wanted.isEmpty()) {
            return List.of();
        }
        int segment = wanted.length() - 1 - Math.max(wanted.lastIndexOf('.'), wanted.lastIndexOf(':'));
        int limit = Math.max(1, Math.min(3, segment / 3)) * 2;
        return candidates.stream().distinct().filter(c -> !c.equals(wanted))
                .filter(c -> cost(wanted, c) <= limit)
                .sorted(Comparator.comparingInt((String c) -> cost(wanted, c)).thenComparing(c -> c))
                .limit(MAX).collect(Collectors.toList());
    }

    /**
     * Whether {@code a} looks like a mistyped {@code b} (or the reverse): one or two edits apart
     * (a swap of neighbours is one), fewer than half the shorter name, and not two names of one
     * family that differ in a single one-letter or numeric word ({@code x_input}/{@code y_input},
     * {@code pose1}/{@code pose2}), which are written that way on purpose.
     */
    public static boolean isTypo(String a, String b) {
        int edits = distance(a, b);
        if (edits < 1 || edits > 2 || 2 * edits >= Math.min(a.length(), b.length())) {
            return false;
        }
        List<String> wordsA = words(a);
        List<String> wordsB = words(b);
        if (wordsA.size() != wordsB.size()) {
            return true;
        }
        List<Integer> differing = new java.util.ArrayList<>();
        for (int i = 0; i < wordsA.size(); i++) {
            if (!wordsA.get(i).equals(wordsB.get(i))) {
                differing.add(i);
            }
        }
        if (differing.size() != 1) {
            return true;
        }
        String wordA = wordsA.get(differing.get(0));
        String wordB = wordsB.get(differing.get(0));
        boolean family = wordA.length() == 1 && wordB.length() == 1 || wordA.matches("\\d+") && wordB.matches("\\d+");
        return !family;
    }

    /** A name's words: split at _ - . and at lower-to-upper case and letter-digit changes. */
    private static List<String> words(String name) {
        return List.of(name.split("[_\\-.]+|(?<=\\p{Ll})(?=\\p{Lu})|(?<=\\p{L})(?=\\d)|(?<=\\d)(?=\\p{L})"));
    }

    /** Twice the edit distance ignoring case, plus one if the spellings also differ in case. */
    private static int cost(String a, String b) {
        int folded = distance(a.toLowerCase(Locale.ROOT), b.toLowerCase(Locale.ROOT));
        return 2 * folded + (folded == distance(a, b) ? 0 : 1);
    }

    /**
     * Optimal string alignment distance: insertions, deletions, substitutions and swaps of two
     * adjacent characters (the commonest typo, Mian for Main) each count as one edit.
     */
    public static int distance(String a, String b) {
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
                d[i][j] = Math.min(d[i - 1][j - 1] + cost, Math.min(d[i - 1][j], d[i][j - 1]) + 1);
                if (i > 1 && j > 1 && a.charAt(i - 1) == b.charAt(j - 2) && a.charAt(i - 2) == b.charAt(j - 1)) {
                    d[i][j] = Math.min(d[i][j], d[i - 2][j - 2] + 1);
                }
            }
        }
        return d[a.length()][b.length()];
    }
}
