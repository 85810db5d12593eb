package org.miron.bt.script;

import java.util.List;

/**
 * BT.CPP rejects a number directly followed by '.', a letter or '_' ({@code 1..2}, {@code 5.},
 * {@code 12abc}: "invalid suffix"), which a maximal-munch lexer splits into other tokens or
 * reports confusingly. Found by scanning the text, outside string literals, before parsing.
 */
final class NumberSuffixes {
    private NumberSuffixes() {
    }

    static void check(String text, List<ScriptSyntaxError> errors) {
        int i = 0;
        while (i < text.length()) {
            char c = text.charAt(i);
            if (c == '\'' || c == '"') {
                int close = text.indexOf(c, i + 1);
                i = close < 0 ? text.length() : close + 1;
            } else if (Character.isLetter(c) || c == '_' || c == '@') {
                while (i < text.length() && isNameChar(text.charAt(i))) {
                    i++;
                }
            } else if (Character.isDigit(c)) {
                int end = numberEnd(text, i);
                if (end < text.length() && (text.charAt(end) == '.' || isNameChar(text.charAt(end)))) {
                    errors.add(new ScriptSyntaxError(end, 1, "invalid suffix on number literal"));
                }
                i = end;
            } else {
                i++;
            }
        }
    }

    /** The end of the NUMBER token starting at {@code start} (see BtScript.xtext). */
    private static int numberEnd(String text, int start) {
        int i = start;
        if (text.startsWith("0x", i) || text.startsWith("0X", i)) {
            i += 2;
            while (i < text.length() && Character.digit(text.charAt(i), 16) >= 0) {
                i++;
            }
            return i;
        }
        i = digits(text, i);
        if (i + 1 < text.length() && text.charAt(i) == '.' && Character.isDigit(text.charAt(i + 1))) {
            i = digits(text, i + 1);
        }
        if (i < text.length() && (text.charAt(i) == 'e' || text.charAt(i) == 'E')) {
            int exponent = i + 1;
            if (exponent < text.length() && (text.charAt(exponent) == '+' || text.charAt(exponent) == '-')) {
                exponent++;
            }
            if (exponent < text.length() && Character.isDigit(text.charAt(exponent))) {
                i = digits(text, exponent);
            }
        }
        return i;
    }

    private static int digits(String text, int i) {
        while (i < text.length() && Character.isDigit(text.charAt(i))) {
            i++;
        }
        return i;
    }

    private static boolean isNameChar(char c) {
        return Character.isLetterOrDigit(c) || c == '_' || c == '@';
    }
}
