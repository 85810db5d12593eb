package org.miron.bt.script;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

/** ANTLR's messages, in the words a script author uses ("unexpected ';'" rather than "no viable alternative"). */
final class SyntaxMessages {
    private static final Pattern INPUT = Pattern.compile("(?:no viable alternative at input|mismatched input|extraneous input) '(.*?)'");
    private static final Pattern MISSING = Pattern.compile("missing (\\S+) at '(.*?)'");
    private static final Pattern CHARACTER = Pattern.compile("at character '(.*?)'");

    private SyntaxMessages() {
    }

    static String rephrase(String message) {
        Matcher input = INPUT.matcher(message);
        if (input.find()) {
            return input.group(1).equals("<EOF>") ? "the script ends too early (a trailing ';' or a missing operand)"
                    : "unexpected '" + input.group(1) + "' (expected an operand, an operator or ';')";
        }
        Matcher missing = MISSING.matcher(message);
        if (missing.find()) {
            return "missing " + missing.group(1) + " before '" + missing.group(2) + "'";
        }
        Matcher character = CHARACTER.matcher(message);
        if (character.find()) {
            return "unexpected character '" + character.group(1) + "'";
        }
        return message;
    }
}
