package org.miron.executor;

import java.util.Locale;

/**
 * Converts port values, which are literal strings or whatever a node wrote to the blackboard, to
 * the type a node reads, as BehaviorTree.CPP's convertFromString does. Failures throw
 * IllegalArgumentException naming the value.
 */
public final class Conversions {
    private Conversions() {
    }

    public static String toStringValue(Object value) {
        if (value instanceof Double d && d == Math.rint(d) && !d.isInfinite() && Math.abs(d) < 1e15) {
            // 2.0 written by a Java action should compare equal to the literal "2"
            return Long.toString(d.longValue());
        }
        return String.valueOf(value);
    }

    public static int toInt(Object value) {
        if (value instanceof Integer || value instanceof Long || value instanceof Short || value instanceof Byte) {
            return Math.toIntExact(((Number) value).longValue());
        }
        if (value instanceof Number n) {
            return wholeNumber(n.doubleValue(), value);
        }
        String text = String.valueOf(value).trim();
        try {
            return Integer.parseInt(text);
        } catch (NumberFormatException notAnInt) {
            try {
                // "3.0" is an integer too; "3.5" is not (BT.CPP's stoi would silently truncate it)
                return wholeNumber(Double.parseDouble(text), value);
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("not an integer: '" + value + "'");
            }
        }
    }

    private static int wholeNumber(double d, Object original) {
        if (d != Math.rint(d) || d > Integer.MAX_VALUE || d < Integer.MIN_VALUE) {
            throw new IllegalArgumentException("not an integer: '" + original + "'");
        }
        return (int) d;
    }

    public static double toDouble(Object value) {
        if (value instanceof Number n) {
            return n.doubleValue();
        }
        try {
            return Double.parseDouble(String.valueOf(value).trim());
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("not a number: '" + value + "'");
        }
    }

    /** 0/1/true/false in any case, as BehaviorTree.CPP 3 accepts. */
    public static boolean toBoolean(Object value) {
        if (value instanceof Boolean b) {
            return b;
        }
        if (value instanceof Number n && (n.doubleValue() == 0 || n.doubleValue() == 1)) {
            return n.doubleValue() == 1;
        }
        String text = String.valueOf(value).trim().toLowerCase(Locale.ROOT);
        switch (text) {
            case "1":
            case "true":
                return true;
            case "0":
            case "false":
                return false;
            default:
                throw new IllegalArgumentException("not a boolean (0/1/true/false): '" + value + "'");
        }
    }

    /** RUNNING, SUCCESS or FAILURE in any case (return_on_mismatch). */
    public static NodeStatus toStatus(Object value) {
        if (value instanceof NodeStatus s) {
            return s;
        }
        String text = String.valueOf(value).trim().toUpperCase(Locale.ROOT);
        switch (text) {
            case "RUNNING":
                return NodeStatus.RUNNING;
            case "SUCCESS":
                return NodeStatus.SUCCESS;
            case "FAILURE":
                return NodeStatus.FAILURE;
            default:
                throw new IllegalArgumentException("not a node status (RUNNING/SUCCESS/FAILURE): '" + value + "'");
        }
    }

    /** As {@link #toStatus}, SKIPPED accepted too (version-4 ports such as if_empty and else). */
    public static NodeStatus toStatusOrSkipped(Object value) {
        if (String.valueOf(value).trim().equalsIgnoreCase("SKIPPED")) {
            return NodeStatus.SKIPPED;
        }
        return toStatus(value);
    }

    /**
     * A literal as a skill or action argument: an integer or a number when it reads as one, else
     * the string itself.
     */
    public static Object toScalar(String literal) {
        String text = literal.trim();
        try {
            return Integer.parseInt(text);
        } catch (NumberFormatException notInt) {
            try {
                double d = Double.parseDouble(text);
                if (!Double.isNaN(d) && !Double.isInfinite(d) && text.matches("[-+]?[0-9.]+([eE][-+]?[0-9]+)?")) {
                    return d;
                }
            } catch (NumberFormatException notNumber) {
                // a plain string
            }
        }
        return literal;
    }
}
