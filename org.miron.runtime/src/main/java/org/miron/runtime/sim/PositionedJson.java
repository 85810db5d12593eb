package org.miron.runtime.sim;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonPointer;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.util.HashMap;
import java.util.Map;
import org.miron.runtime.Json;

/**
 * A JSON document read with the line and column of every value, by JSON pointer, so that a world
 * file's mistakes are reported where they are ({@code file:line:col}) and not only by pointer.
 */
public final class PositionedJson {
    /** Where a value starts: 1-based line and column. */
    public record Position(int line, int column) {
    }

    /** Suffix of the pointer under which a member's name (not its value) is placed. */
    static final String KEY = "#key";

    private final JsonNode root;
    private final Map<String, Position> positions;

    private PositionedJson(JsonNode root, Map<String, Position> positions) {
        this.root = root;
        this.positions = positions;
    }

    /** Parses {@code text}; a syntax error comes back as a {@link JsonProcessingException} with its location. */
    public static PositionedJson parse(String text) throws IOException {
        Map<String, Position> positions = new HashMap<>();
        try (JsonParser p = Json.MAPPER.getFactory().createParser(text)) {
            if (p.nextToken() == null) {
                throw new com.fasterxml.jackson.core.JsonParseException(p, "the file is empty");
            }
            JsonNode root = read(p, "", positions);
            if (p.nextToken() != null) {
                throw new com.fasterxml.jackson.core.JsonParseException(p, "trailing content after the JSON value");
            }
            return new PositionedJson(root, positions);
        }
    }

    private static JsonNode read(JsonParser p, String pointer, Map<String, Position> positions) throws IOException {
        JsonLocation at = p.getTokenLocation();
        positions.put(pointer, new Position(at.getLineNr(), at.getColumnNr()));
        JsonNodeFactory f = JsonNodeFactory.instance;
        JsonToken t = p.currentToken();
        switch (t) {
            case START_OBJECT -> {
                ObjectNode o = f.objectNode();
                while (p.nextToken() == JsonToken.FIELD_NAME) {
                    String name = p.currentName();
                    JsonLocation key = p.getTokenLocation();
                    positions.put(pointer + "/" + escape(name) + KEY, new Position(key.getLineNr(), key.getColumnNr()));
                    p.nextToken();
                    o.set(name, read(p, pointer + "/" + escape(name), positions));
                }
                return o;
            }
            case START_ARRAY -> {
                ArrayNode a = f.arrayNode();
                int i = 0;
                while (p.nextToken() != JsonToken.END_ARRAY) {
                    a.add(read(p, pointer + "/" + i++, positions));
                }
                return a;
            }
            case VALUE_STRING -> {
                return f.textNode(p.getText());
            }
            case VALUE_NUMBER_INT -> {
                return f.numberNode(p.getLongValue());
            }
            case VALUE_NUMBER_FLOAT -> {
                return f.numberNode(p.getDoubleValue());
            }
            case VALUE_TRUE, VALUE_FALSE -> {
                return f.booleanNode(t == JsonToken.VALUE_TRUE);
            }
            default -> {
                return f.nullNode();
            }
        }
    }

    private static String escape(String name) {
        return name.replace("~", "~0").replace("/", "~1");
    }

    public JsonNode root() {
        return root;
    }

    /** The position of the value at {@code pointer}, or of its closest enclosing value. */
    public Position at(String pointer) {
        String p = pointer;
        while (true) {
            Position pos = positions.get(p);
            if (pos != null || p.isEmpty()) {
                return pos == null ? new Position(1, 1) : pos;
            }
            p = JsonPointer.compile(p).head().toString();
        }
    }

    /** Where the name of the member at {@code pointer} is written (its value's position if unknown). */
    public Position keyAt(String pointer) {
        Position p = positions.get(pointer + KEY);
        return p != null ? p : at(pointer);
    }

    /** A pointer to a field of an object at {@code pointer}. */
    public static String child(String pointer, String field) {
        return pointer + "/" + escape(field);
    }
}
