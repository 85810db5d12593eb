package org.miron.dds.config;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.util.HashMap;
import java.util.Map;

/**
 * A JSON document with the position of every value, by JSON pointer: Jackson's trees forget where
 * a value was, and a start-up error must say {@code file:line:col}. Duplicate keys are an error.
 */
final class Located {
    private static final JsonNodeFactory F = JsonNodeFactory.instance;
    final JsonNode root;
    private final Map<String, int[]> positions = new HashMap<>();

    private Located(JsonParser p) throws IOException, ConfigException {
        JsonToken first = p.nextToken();
        if (first == null) {
            throw new ConfigException(1, 1, "", "empty file: a JSON object is expected");
        }
        root = value(p, "");
        if (p.nextToken() != null) {
            JsonLocation l = p.currentTokenLocation();
            throw new ConfigException(l.getLineNr(), l.getColumnNr(), "", "trailing content after the JSON object");
        }
    }

    static Located parse(String text) throws ConfigException {
        try (JsonParser p = new JsonFactory().createParser(text)) {
            return new Located(p);
        } catch (ConfigException e) {
            throw e;
        } catch (com.fasterxml.jackson.core.JsonProcessingException e) {
            JsonLocation l = e.getLocation();
            throw new ConfigException(l == null ? 1 : l.getLineNr(), l == null ? 1 : l.getColumnNr(), "",
                    "not valid JSON: " + e.getOriginalMessage());
        } catch (IOException e) {
            throw new ConfigException(1, 1, "", "cannot read: " + e.getMessage());
        }
    }

    /** Line and column of the value at {@code pointer}, or of the closest enclosing value. */
    int[] position(String pointer) {
        String p = pointer;
        while (true) {
            int[] pos = positions.get(p);
            if (pos != null || p.isEmpty()) {
                return pos == null ? new int[] {1, 1} : pos;
            }
            p = p.substring(0, p.lastIndexOf('/'));
        }
    }

    private JsonNode value(JsonParser p, String pointer) throws IOException, ConfigException {
        JsonLocation l = p.currentTokenLocation();
        positions.put(pointer, new int[] {l.getLineNr(), l.getColumnNr()});
        switch (p.currentToken()) {
            case START_OBJECT: {
                ObjectNode o = F.objectNode();
                while (p.nextToken() == JsonToken.FIELD_NAME) {
                    String name = p.currentName();
                    String child = pointer + "/" + name.replace("~", "~0").replace("/", "~1");
                    if (o.has(name)) {
                        JsonLocation k = p.currentTokenLocation();
                        throw new ConfigException(k.getLineNr(), k.getColumnNr(), child, "duplicate key \"" + name + "\"");
                    }
                    p.nextToken();
                    o.set(name, value(p, child));
                }
                return o;
            }
            case START_ARRAY: {
                ArrayNode a = F.arrayNode();
                while (p.nextToken() != JsonToken.END_ARRAY) {
                    a.add(value(p, pointer + "/" + a.size()));
                }
                return a;
            }
            case VALUE_STRING:
                return F.textNode(p.getText());
            case VALUE_NUMBER_INT:
                return F.numberNode(p.getLongValue());
            case VALUE_NUMBER_FLOAT:
                return F.numberNode(p.getDoubleValue());
            case VALUE_TRUE:
                return F.booleanNode(true);
            case VALUE_FALSE:
                return F.booleanNode(false);
            default:
                return F.nullNode();
        }
    }
}
