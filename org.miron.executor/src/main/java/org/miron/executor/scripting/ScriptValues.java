package org.miron.executor.scripting;

import java.util.Locale;
import java.util.Map;
import org.miron.executor.Conversions;

/**
 * The values of the version-4 scripting language and their conversions, following BT.CPP 4's
 * SafeAny: integers are Long, reals Double, text String; true and false are the integers 1 and 0.
 * Whatever a Java action wrote to the blackboard is read the same way (Boolean and Integer as
 * Long, Float as Double); anything else is text.
 */
public final class ScriptValues {
    private ScriptValues() {
    }

    /** A blackboard value as a script value. */
    public static Object of(Object value) {
        if (value == null || value instanceof Long || value instanceof Double || value instanceof String) {
            return value;
        }
        if (value instanceof Boolean b) {
            return b ? 1L : 0L;
        }
        if (value instanceof Integer || value instanceof Short || value instanceof Byte) {
            return ((Number) value).longValue();
        }
        if (value instanceof Float f) {
            return f.doubleValue();
        }
        return String.valueOf(value);
    }

    public static boolean isNumber(Object value) {
        return value instanceof Long || value instanceof Double;
    }

    /** A number as a double; text that reads as a number too (BT.CPP's cast&lt;double&gt;). */
    public static double toDouble(Object value) {
        try {
            return Conversions.toDouble(value);
        } catch (IllegalArgumentException e) {
            throw new ScriptException("'" + value + "' is not a number");
        }
    }

    /**
     * Text compared with a number: true, false and enum names count as their numbers
     * (BT.CPP's StringToDouble).
     */
    static double textToDouble(String text, Map<String, Integer> enums) {
        if (text.equals("true")) {
            return 1;
        }
        if (text.equals("false")) {
            return 0;
        }
        Integer value = enums.get(text);
        return value != null ? value : toDouble(text);
    }

    /** An integral value as a long; a real only when it has no fraction. */
    static long toLong(Object value) {
        if (value instanceof Long l) {
            return l;
        }
        double d = toDouble(value);
        if (d != Math.rint(d) || d > Long.MAX_VALUE || d < Long.MIN_VALUE) {
            throw new ScriptException("Invalid floating point to integer conversion: " + value);
        }
        return (long) d;
    }

    /**
     * A script value as a condition (BT.CPP's cast&lt;bool&gt;): a real is true unless 0, an
     * integer must be 0 or 1, text is refused.
     */
    public static boolean toBoolean(Object value) {
        if (value instanceof Double d) {
            return d != 0;
        }
        if (value instanceof Long l) {
            if (l != 0 && l != 1) {
                throw new ScriptException("Implicit casting to bool is not allowed: " + l);
            }
            return l == 1;
        }
        if (value == null) {
            throw new ScriptException("the script has no value");
        }
        throw new ScriptException("no known safe conversion from text ('" + value + "') to a boolean");
    }

    /** A value as text: integers plainly, reals with six decimals (C++'s std::to_string). */
    public static String toText(Object value) {
        if (value instanceof Double d) {
            return String.format(Locale.ROOT, "%f", d);
        }
        return String.valueOf(value);
    }
}
