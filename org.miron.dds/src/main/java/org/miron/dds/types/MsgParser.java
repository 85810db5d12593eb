package org.miron.dds.types;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * A ROS 2 {@code .msg} file (rosidl's grammar): one field {@code TYPE name [default]} or constant
 * {@code TYPE NAME=value} per line, {@code #} comments. Types are primitives (a string maybe
 * bounded, {@code string<=10}), {@code pkg/Name} or a bare {@code Name} of the same package, with
 * {@code []}, {@code [N]} or {@code [<=N]}. Nested names are left unresolved here: the
 * {@link TypeRegistry} checks them once every package is loaded. Errors point at the token.
 */
public final class MsgParser {
    private static final Pattern TYPE = Pattern.compile(
            "(?:([a-z][a-z0-9_]*)/)?([A-Za-z][A-Za-z0-9_]*)(?:<=([0-9]+))?(?:\\[(<=)?([0-9]*)\\])?");
    private static final Pattern FIELD_NAME = Pattern.compile("[a-z][a-z0-9_]*");
    private static final Pattern CONSTANT_NAME = Pattern.compile("[A-Z][A-Z0-9_]*");

    private final String file;
    private final String pkg;

    private MsgParser(String file, String pkg) {
        this.file = file;
        this.pkg = pkg;
    }

    /** The message {@code pkg/name} defined by {@code text}, read from {@code file} (for errors). */
    public static MsgType parse(String file, String pkg, String name, String text) throws DefinitionException {
        return new MsgParser(file, pkg).parse(name, text);
    }

    private DefinitionException error(int line, int col, String why) {
        return new DefinitionException(file, line, col, why);
    }

    private MsgType parse(String name, String text) throws DefinitionException {
        List<MsgField> fields = new ArrayList<>();
        Map<String, JsonNode> constants = new LinkedHashMap<>();
        String[] lines = text.split("\r?\n", -1);
        for (int i = 0; i < lines.length; i++) {
            int ln = i + 1;
            String line = lines[i];
            int start = firstNonSpace(line, 0);
            if (start >= line.length() || line.charAt(start) == '#') {
                continue;
            }
            int typeEnd = firstSpace(line, start);
            String typeText = line.substring(start, typeEnd);
            int nameStart = firstNonSpace(line, typeEnd);
            if (nameStart >= line.length() || line.charAt(nameStart) == '#') {
                throw error(ln, typeEnd + 1, "a field needs a name after its type " + typeText);
            }
            int nameEnd = nameStart;
            while (nameEnd < line.length() && !Character.isWhitespace(line.charAt(nameEnd)) && line.charAt(nameEnd) != '='
                    && line.charAt(nameEnd) != '#') {
                nameEnd++;
            }
            String fieldName = line.substring(nameStart, nameEnd);
            int after = firstNonSpace(line, nameEnd);
            FieldType type = type(typeText, ln, start + 1);
            if (after < line.length() && line.charAt(after) == '=') {
                constants.put(fieldName, constant(type, fieldName, line, ln, nameStart, after + 1));
                continue;
            }
            if (!FIELD_NAME.matcher(fieldName).matches() || fieldName.contains("__") || fieldName.endsWith("_")) {
                throw error(ln, nameStart + 1, "a field name is lower case letters, digits and single underscores,"
                        + " starting with a letter: " + fieldName);
            }
            for (MsgField f : fields) {
                if (f.name().equals(fieldName)) {
                    throw error(ln, nameStart + 1, "field " + fieldName + " is defined twice (first at line " + f.line() + ")");
                }
            }
            JsonNode dflt = null;
            if (after < line.length() && line.charAt(after) != '#') {
                if (type.primitive() == null) {
                    throw error(ln, after + 1, "a nested message field (" + type + ") cannot have a default value");
                }
                String value = valueText(line, after, type.primitive().isString() && !type.isArray());
                try {
                    dflt = type.isArray() ? Values.array(type, value) : Values.scalar(type.primitive(), type.stringBound(), value);
                } catch (Values.Bad e) {
                    throw error(ln, after + 1, "bad default of " + fieldName + ": " + e.getMessage());
                }
            }
            fields.add(new MsgField(fieldName, type, dflt, ln, start + 1));
        }
        return new MsgType(pkg, name, fields, constants, file);
    }

    private JsonNode constant(FieldType type, String name, String line, int ln, int nameStart, int valueStart) throws DefinitionException {
        if (type.primitive() == null || type.isArray()) {
            throw error(ln, nameStart + 1, "constant " + name + " must be of a primitive type, not " + type);
        }
        if (!CONSTANT_NAME.matcher(name).matches()) {
            throw error(ln, nameStart + 1, "a constant name is upper case letters, digits and underscores: " + name);
        }
        int v = firstNonSpace(line, valueStart);
        String value = valueText(line, v, type.primitive().isString());
        if (value.isEmpty() && !type.primitive().isString()) {
            throw error(ln, valueStart + 1, "constant " + name + " needs a value");
        }
        try {
            return Values.scalar(type.primitive(), type.stringBound(), value);
        } catch (Values.Bad e) {
            throw error(ln, v + 1, "bad value of constant " + name + ": " + e.getMessage());
        }
    }

    /** The value's text from {@code from}: a string runs to the end of the line (quotes keep a '#'), anything else to a comment. */
    private static String valueText(String line, int from, boolean string) {
        String rest = line.substring(Math.min(from, line.length()));
        if (string) {
            String t = rest.trim();
            if (t.startsWith("\"") || t.startsWith("'")) {
                int close = t.indexOf(t.charAt(0), 1);
                return close > 0 ? t.substring(0, close + 1) : t;
            }
            int hash = rest.indexOf('#');
            return (hash >= 0 ? rest.substring(0, hash) : rest).trim();
        }
        int hash = rest.indexOf('#');
        return (hash >= 0 ? rest.substring(0, hash) : rest).trim();
    }

    /** A type token; {@code col} is where it starts, for errors. */
    FieldType type(String text, int ln, int col) throws DefinitionException {
        Matcher m = TYPE.matcher(text);
        if (!m.matches()) {
            throw error(ln, col, "not a type: " + text + " (a primitive, pkg/Name or Name, with [], [N] or [<=N])");
        }
        FieldType.Array array = FieldType.Array.NONE;
        int size = -1;
        if (text.contains("[")) {
            if (m.group(4) != null) {
                if (m.group(5).isEmpty()) {
                    throw error(ln, col, "a bounded array needs its bound: " + text);
                }
                array = FieldType.Array.BOUNDED;
                size = Integer.parseInt(m.group(5));
            } else if (m.group(5).isEmpty()) {
                array = FieldType.Array.UNBOUNDED;
            } else {
                array = FieldType.Array.FIXED;
                size = Integer.parseInt(m.group(5));
            }
        }
        String pkgPart = m.group(1);
        String base = m.group(2);
        int bound = m.group(3) == null ? -1 : Integer.parseInt(m.group(3));
        if (pkgPart == null) {
            Primitive p = Primitive.ofMsg(base);
            if (p != null) {
                if (bound >= 0 && !p.isString()) {
                    throw error(ln, col, "only strings have a bound (<=N), not " + base);
                }
                return new FieldType(p, null, bound, array, size);
            }
            if (base.equals("time") || base.equals("duration")) { // ROS 1 spellings rosidl still reads
                return new FieldType(null, "builtin_interfaces/" + (base.equals("time") ? "Time" : "Duration"), -1, array, size);
            }
            if (Character.isLowerCase(base.charAt(0))) {
                throw error(ln, col, "unknown type " + base + " (not a primitive: bool, byte, char, float32, float64, int8 ... uint64,"
                        + " string, wstring; a message type is CamelCase)" + suggestion(base));
            }
            if (bound >= 0) {
                throw error(ln, col, "only strings have a bound (<=N), not " + base);
            }
            return new FieldType(null, (base.equals("Header") && !pkg.equals("std_msgs") ? "std_msgs" : pkg) + "/" + base, -1, array, size);
        }
        if (bound >= 0 || !Character.isUpperCase(base.charAt(0))) {
            throw error(ln, col, "not a message type: " + text + " (pkg/Name, Name in CamelCase)");
        }
        return new FieldType(null, pkgPart + "/" + base, -1, array, size);
    }

    /** ", did you mean float32?" for a misspelled primitive. */
    private static String suggestion(String word) {
        String best = null;
        int bestD = 3;
        for (Primitive p : Primitive.values()) {
            int d = distance(word, p.msgName());
            if (d < bestD) {
                bestD = d;
                best = p.msgName();
            }
        }
        return best == null ? "" : "; did you mean " + best + "?";
    }

    private static int distance(String a, String b) {
        int[][] d = new int[a.length() + 1][b.length() + 1];
        for (int i = 0; i <= a.length(); i++) {
            for (int j = 0; j <= b.length(); j++) {
                if (i == 0 || j == 0) {
                    d[i][j] = i + j;
                } else {
                    int sub = d[i - 1][j - 1] + (a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1);
                    d[i][j] = Math.min(sub, Math.min(d[i - 1][j], d[i][j - 1]) + 1);
                    if (i > 1 && j > 1 && a.charAt(i - 1) == b.charAt(j - 2) && a.charAt(i - 2) == b.charAt(j - 1)) {
                        d[i][j] = Math.min(d[i][j], d[i - 2][j - 2] + 1); // a swap, as in flaot32
                    }
                }
            }
        }
        return d[a.length()][b.length()];
    }

    private static int firstNonSpace(String s, int from) {
        int i = from;
        while (i < s.length() && Character.isWhitespace(s.charAt(i))) {
            i++;
        }
        return i;
    }

    private static int firstSpace(String s, int from) {
        int i = from;
        while (i < s.length() && !Character.isWhitespace(s.charAt(i))) {
            i++;
        }
        return i;
    }
}
