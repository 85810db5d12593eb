package org.miron.bt.script;

import java.util.Locale;

/** Values of the scripting language's number literals, as written in the AST (NumberLiteral.text). */
public final class ScriptLiterals {
    private ScriptLiterals() {
    }

    /** True for a literal with a fraction or an exponent; hexadecimal literals are integers. */
    public static boolean isReal(String text) {
        String lower = text.toLowerCase(Locale.ROOT);
        return !lower.startsWith("0x") && (lower.indexOf('.') >= 0 || lower.indexOf('e') >= 0);
    }

    /** The literal's value; integers beyond 2^53 lose precision, as doubles do. */
    public static double value(String text) {
        String lower = text.toLowerCase(Locale.ROOT);
        if (lower.startsWith("0x")) {
            return Long.parseUnsignedLong(lower.substring(2), 16);
        }
        return isReal(text) ? Double.parseDouble(text) : Long.parseLong(text);
    }
}
