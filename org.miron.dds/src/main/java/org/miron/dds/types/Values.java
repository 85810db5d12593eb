package org.miron.dds.types;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import java.math.BigInteger;

/**
 * Literal values of definitions (constants and defaults) as JSON, checked against their primitive:
 * the range of an integer, a bool's spellings, a bounded string's length. Shared by both parsers.
 */
final class Values {
    private static final JsonNodeFactory F = JsonNodeFactory.instance;

    private Values() {
    }

    /** Why a literal is refused. */
    static final class Bad extends Exception {
        private static final long serialVersionUID = 1L;

        Bad(String why) {
            super(why);
        }
    }

    /** The zero value ROS 2 gives a field of this type: 0, false, "", an array of zeros or empty, a nested default. */
    static JsonNode zero(Primitive p) {
        return switch (p) {
            case BOOL -> F.booleanNode(false);
            case STRING, WSTRING -> F.textNode("");
            case FLOAT32, FLOAT64 -> F.numberNode(0.0);
            default -> F.numberNode(0L);
        };
    }

    /** One literal of a primitive type, e.g. {@code 5}, {@code -1.5e3}, {@code true}, {@code "a b"}. */
    static JsonNode scalar(Primitive p, int stringBound, String text) throws Bad {
        String t = text.trim();
        if (p.isString()) {
            String s = unquote(t);
            if (stringBound >= 0 && s.length() > stringBound) {
                throw new Bad("\"" + s + "\" is longer than the bound " + stringBound);
            }
            return F.textNode(s);
        }
        if (p == Primitive.BOOL) {
            return switch (t.toLowerCase(java.util.Locale.ROOT)) {
                case "true", "1" -> F.booleanNode(true);
                case "false", "0" -> F.booleanNode(false);
                default -> throw new Bad("a bool is true or false, not " + t);
            };
        }
        if (p.isFloat()) {
            try {
                return F.numberNode(Double.parseDouble(t));
            } catch (NumberFormatException e) {
                throw new Bad("not a number for a " + p.msgName() + ": " + t);
            }
        }
        BigInteger v;
        try {
            v = t.toLowerCase(java.util.Locale.ROOT).startsWith("0x") ? new BigInteger(t.substring(2), 16) : new BigInteger(t);
        } catch (NumberFormatException e) {
            throw new Bad("not an integer for a " + p.msgName() + ": " + t);
        }
        BigInteger[] range = range(p);
        if (v.compareTo(range[0]) < 0 || v.compareTo(range[1]) > 0) {
            throw new Bad(t + " is out of the range of a " + p.msgName() + " (" + range[0] + " to " + range[1] + ")");
        }
        return p == Primitive.UINT64 && v.bitLength() > 63 ? F.numberNode(v) : F.numberNode(v.longValue());
    }

    /** A literal of an array type: {@code [1, 2, 3]}; its length checked against a fixed or bounded array. */
    static JsonNode array(FieldType type, String text) throws Bad {
        String t = text.trim();
        if (!t.startsWith("[") || !t.endsWith("]")) {
            throw new Bad("an array default is written [a, b, ...], not " + t);
        }
        ArrayNode a = F.arrayNode();
        String inner = t.substring(1, t.length() - 1).trim();
        if (!inner.isEmpty()) {
            for (String item : splitItems(inner)) {
                a.add(scalar(type.primitive(), type.stringBound(), item));
            }
        }
        if (type.array() == FieldType.Array.FIXED && a.size() != type.size()) {
            throw new Bad("the array has " + type.size() + " elements, the default gives " + a.size());
        }
        if (type.array() == FieldType.Array.BOUNDED && a.size() > type.size()) {
            throw new Bad("the array holds at most " + type.size() + " elements, the default gives " + a.size());
        }
        return a;
    }

    /** Items separated by commas outside quotes. */
    private static java.util.List<String> splitItems(String s) {
        java.util.List<String> out = new java.util.ArrayList<>();
        StringBuilder cur = new StringBuilder();
        char quote = 0;
        for (char c : s.toCharArray()) {
            if (quote != 0) {
                if (c == quote) {
                    quote = 0;
                }
            } else if (c == '"' || c == '\'') {
                quote = c;
            } else if (c == ',') {
                out.add(cur.toString());
                cur.setLength(0);
                continue;
            }
            cur.append(c);
        }
        out.add(cur.toString());
        return out;
    }

    static String unquote(String t) {
        if (t.length() >= 2 && (t.startsWith("\"") && t.endsWith("\"") || t.startsWith("'") && t.endsWith("'"))) {
            return t.substring(1, t.length() - 1).replace("\\\"", "\"").replace("\\'", "'");
        }
        return t;
    }

    private static BigInteger[] range(Primitive p) {
        return switch (p) {
            case INT8 -> bits(8, true);
            case INT16 -> bits(16, true);
            case INT32 -> bits(32, true);
            case INT64 -> bits(64, true);
            case UINT16 -> bits(16, false);
            case UINT32 -> bits(32, false);
            case UINT64 -> bits(64, false);
            default -> bits(8, false); // byte, char, uint8
        };
    }

    private static BigInteger[] bits(int n, boolean signed) {
        return signed ? new BigInteger[] {BigInteger.ONE.shiftLeft(n - 1).negate(), BigInteger.ONE.shiftLeft(n - 1).subtract(BigInteger.ONE)}
                : new BigInteger[] {BigInteger.ZERO, BigInteger.ONE.shiftLeft(n).subtract(BigInteger.ONE)};
    }
}
