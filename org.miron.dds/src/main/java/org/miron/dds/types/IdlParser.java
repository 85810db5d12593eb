package org.miron.dds.types;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * An {@code .idl} file as ROS 2's rosidl generates them from .msg files ({@code module pkg { module
 * msg { struct Name { ... }; }; };}): structs of primitives, {@code string<N>},
 * {@code sequence<T[, N]>}, arrays {@code name[N]} and rosidl's array typedefs, nested types as
 * {@code pkg::msg::Name}, {@code @default (value=...)}, constants in {@code Name_Constants}
 * modules. Other annotations are skipped; {@code #include} lines are ignored (the packages to load
 * are the configuration's). Not a general IDL compiler: unions, enums and the like are refused.
 */
public final class IdlParser {
    private static final Map<String, Primitive> PRIMITIVES = Map.ofEntries(Map.entry("boolean", Primitive.BOOL),
            Map.entry("octet", Primitive.BYTE), Map.entry("char", Primitive.CHAR), Map.entry("wchar", Primitive.UINT16),
            Map.entry("int8", Primitive.INT8), Map.entry("uint8", Primitive.UINT8), Map.entry("int16", Primitive.INT16),
            Map.entry("uint16", Primitive.UINT16), Map.entry("int32", Primitive.INT32), Map.entry("uint32", Primitive.UINT32),
            Map.entry("int64", Primitive.INT64), Map.entry("uint64", Primitive.UINT64), Map.entry("short", Primitive.INT16),
            Map.entry("long", Primitive.INT32), Map.entry("float", Primitive.FLOAT32), Map.entry("double", Primitive.FLOAT64),
            Map.entry("string", Primitive.STRING), Map.entry("wstring", Primitive.WSTRING));

    private final String file;
    private final IdlTokens in;
    private final Map<String, FieldType> typedefs = new HashMap<>();
    private final Map<String, Map<String, JsonNode>> constants = new HashMap<>();
    private final List<MsgType> out = new ArrayList<>();
    private final List<String> modules = new ArrayList<>();

    private IdlParser(String file, String text) {
        this.file = file;
        this.in = new IdlTokens(file, text);
    }

    /** The structs {@code text} defines, each with the constants of its {@code Name_Constants} module. */
    public static List<MsgType> parse(String file, String text) throws DefinitionException {
        IdlParser p = new IdlParser(file, text);
        while (!p.in.atEnd()) {
            p.definition();
        }
        List<MsgType> result = new ArrayList<>();
        for (MsgType t : p.out) {
            Map<String, JsonNode> c = p.constants.getOrDefault(t.pkg() + "/" + t.name(), Map.of());
            result.add(new MsgType(t.pkg(), t.name(), t.fields(), c, t.file()));
        }
        return result;
    }

    private void definition() throws DefinitionException {
        Map<String, String> annotations = annotations();
        IdlTokens.Token t = in.next();
        switch (t.text()) {
            case "module" -> {
                modules.add(in.identifier().text());
                in.expect("{");
                while (!in.peekIs("}")) {
                    definition();
                }
                in.expect("}");
                in.expect(";");
                modules.remove(modules.size() - 1);
            }
            case "struct" -> struct(in.identifier());
            case "typedef" -> {
                FieldType base = type();
                IdlTokens.Token name = in.identifier();
                typedefs.put(name.text(), arrayOf(base, name));
                in.expect(";");
            }
            case "const" -> {
                IdlTokens.Token typeTok = in.peek();
                FieldType type = type();
                IdlTokens.Token name = in.identifier();
                in.expect("=");
                IdlTokens.Token value = in.next();
                in.expect(";");
                if (type.primitive() == null) {
                    throw in.error(typeTok, "a constant is of a primitive type");
                }
                String owner = modules.size() >= 1 ? modules.get(modules.size() - 1) : "";
                if (!owner.endsWith("_Constants") || modules.size() < 3) {
                    throw in.error(name, "a constant belongs in a module Name_Constants inside module pkg { module msg { ... } }");
                }
                String key = modules.get(0) + "/" + owner.substring(0, owner.length() - "_Constants".length());
                try {
                    constants.computeIfAbsent(key, k -> new LinkedHashMap<>()).put(name.text(),
                            Values.scalar(type.primitive(), type.stringBound(), value.text()));
                } catch (Values.Bad e) {
                    throw in.error(value, "bad value of constant " + name.text() + ": " + e.getMessage());
                }
            }
            default -> throw in.error(t, "expected module, struct, typedef or const, found " + t.text()
                    + (annotations.isEmpty() ? "" : " after annotations"));
        }
    }

    private void struct(IdlTokens.Token name) throws DefinitionException {
        if (modules.size() != 2 || !modules.get(1).equals("msg")) {
            throw in.error(name, "a message struct belongs in module pkg { module msg { ... } }, as rosidl writes it");
        }
        in.expect("{");
        List<MsgField> fields = new ArrayList<>();
        while (!in.peekIs("}")) {
            Map<String, String> annotations = annotations();
            IdlTokens.Token typeTok = in.peek();
            FieldType base = type();
            IdlTokens.Token fieldName = in.identifier();
            FieldType type = arrayOf(base, fieldName);
            in.expect(";");
            JsonNode dflt = null;
            if (annotations.containsKey("default")) {
                String v = annotations.get("default");
                try {
                    dflt = type.primitive() == null ? null : type.isArray() ? Values.array(type, Values.unquote(v).replace('(', '[').replace(')', ']'))
                            : Values.scalar(type.primitive(), type.stringBound(), v);
                } catch (Values.Bad e) {
                    throw in.error(typeTok, "bad default of " + fieldName.text() + ": " + e.getMessage());
                }
            }
            fields.add(new MsgField(fieldName.text(), type, dflt, typeTok.line(), typeTok.column()));
        }
        in.expect("}");
        in.expect(";");
        out.add(new MsgType(modules.get(0), name.text(), fields, Map.of(), file));
    }

    /** {@code name[N]} after a field or typedef name: a fixed array. */
    private FieldType arrayOf(FieldType base, IdlTokens.Token name) throws DefinitionException {
        if (!in.peekIs("[")) {
            return base;
        }
        in.expect("[");
        int n = in.integer();
        in.expect("]");
        if (base.isArray()) {
            throw in.error(name, "arrays of arrays are not ROS 2 message fields");
        }
        return new FieldType(base.primitive(), base.message(), base.stringBound(), FieldType.Array.FIXED, n);
    }

    /** Annotations before a definition or member: their name to their {@code value} (or ""). */
    private Map<String, String> annotations() throws DefinitionException {
        Map<String, String> a = new HashMap<>();
        while (in.peekIs("@")) {
            in.next();
            String name = in.identifier().text();
            String value = "";
            if (in.peekIs("(")) {
                value = in.annotationValue();
            }
            a.put(name, value);
        }
        return a;
    }

    private FieldType type() throws DefinitionException {
        IdlTokens.Token t = in.next();
        String s = t.text();
        if (s.equals("sequence")) {
            in.expect("<");
            FieldType element = type();
            int bound = -1;
            if (in.peekIs(",")) {
                in.next();
                bound = in.integer();
            }
            in.expect(">");
            if (element.isArray()) {
                throw in.error(t, "sequences of arrays are not ROS 2 message fields");
            }
            return new FieldType(element.primitive(), element.message(), element.stringBound(),
                    bound < 0 ? FieldType.Array.UNBOUNDED : FieldType.Array.BOUNDED, bound);
        }
        if (s.equals("unsigned")) {
            IdlTokens.Token w = in.next();
            if (w.text().equals("short")) {
                return prim(Primitive.UINT16);
            }
            if (w.text().equals("long")) {
                if (in.peekIs("long")) {
                    in.next();
                    return prim(Primitive.UINT64);
                }
                return prim(Primitive.UINT32);
            }
            throw in.error(w, "unsigned short, long or long long expected");
        }
        if (s.equals("long") && in.peekIs("long")) {
            in.next();
            return prim(Primitive.INT64);
        }
        if (s.equals("long") && in.peekIs("double")) {
            throw in.error(t, "long double has no ROS 2 encoding the bridge supports");
        }
        if ((s.equals("string") || s.equals("wstring")) && in.peekIs("<")) {
            in.next();
            int bound = in.integer();
            in.expect(">");
            return new FieldType(PRIMITIVES.get(s), null, bound, FieldType.Array.NONE, -1);
        }
        Primitive p = PRIMITIVES.get(s);
        if (p != null) {
            return prim(p);
        }
        if (typedefs.containsKey(s)) {
            return typedefs.get(s);
        }
        if (!Character.isLetter(s.charAt(0))) {
            throw in.error(t, "a type expected, found " + s);
        }
        List<String> parts = new ArrayList<>(List.of(s));
        while (in.peekIs("::")) {
            in.next();
            parts.add(in.identifier().text());
        }
        if (parts.size() == 3 && parts.get(1).equals("msg")) {
            return new FieldType(null, parts.get(0) + "/" + parts.get(2), -1, FieldType.Array.NONE, -1);
        }
        if (parts.size() == 1 && Character.isUpperCase(s.charAt(0)) && !modules.isEmpty()) {
            return new FieldType(null, modules.get(0) + "/" + s, -1, FieldType.Array.NONE, -1);
        }
        throw in.error(t, "unknown type " + String.join("::", parts)
                + " (an IDL primitive such as double, int32, boolean, string, or pkg::msg::Name)");
    }

    private static FieldType prim(Primitive p) {
        return new FieldType(p, null, -1, FieldType.Array.NONE, -1);
    }
}
