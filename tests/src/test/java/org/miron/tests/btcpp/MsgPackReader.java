package org.miron.tests.btcpp;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;

/** Reads the MessagePack of a Groot2 BLACKBOARD reply into JSON (the forms JSON values take). */
final class MsgPackReader {
    private static final JsonNodeFactory JSON = JsonNodeFactory.instance;
    private final ByteBuffer in;

    private MsgPackReader(byte[] bytes) {
        in = ByteBuffer.wrap(bytes);
    }

    static JsonNode read(byte[] bytes) {
        return new MsgPackReader(bytes).value();
    }

    private JsonNode value() {
        int b = in.get() & 0xFF;
        if (b <= 0x7F) {
            return JSON.numberNode(b);
        }
        if (b >= 0xE0) {
            return JSON.numberNode((byte) b);
        }
        if ((b & 0xF0) == 0x80) {
            return map(b & 0x0F);
        }
        if ((b & 0xF0) == 0x90) {
            return array(b & 0x0F);
        }
        if ((b & 0xE0) == 0xA0) {
            return text(b & 0x1F);
        }
        switch (b) {
        case 0xC0: return JSON.nullNode();
        case 0xC2: return JSON.booleanNode(false);
        case 0xC3: return JSON.booleanNode(true);
        case 0xCA: return JSON.numberNode(in.getFloat());
        case 0xCB: return JSON.numberNode(in.getDouble());
        case 0xCC: return JSON.numberNode(in.get() & 0xFF);
        case 0xCD: return JSON.numberNode(in.getShort() & 0xFFFF);
        case 0xCE: return JSON.numberNode(in.getInt() & 0xFFFFFFFFL);
        case 0xCF: return JSON.numberNode(in.getLong());
        case 0xD0: return JSON.numberNode(in.get());
        case 0xD1: return JSON.numberNode(in.getShort());
        case 0xD2: return JSON.numberNode(in.getInt());
        case 0xD3: return JSON.numberNode(in.getLong());
        case 0xD9: return text(in.get() & 0xFF);
        case 0xDA: return text(in.getShort() & 0xFFFF);
        case 0xDB: return text(in.getInt());
        case 0xDC: return array(in.getShort() & 0xFFFF);
        case 0xDD: return array(in.getInt());
        case 0xDE: return map(in.getShort() & 0xFFFF);
        case 0xDF: return map(in.getInt());
        default: throw new IllegalArgumentException("MessagePack type 0x" + Integer.toHexString(b) + " not read here");
        }
    }

    private JsonNode text(int n) {
        byte[] utf8 = new byte[n];
        in.get(utf8);
        return JSON.textNode(new String(utf8, StandardCharsets.UTF_8));
    }

    private JsonNode array(int n) {
        ArrayNode array = JSON.arrayNode();
        for (int i = 0; i < n; i++) {
            array.add(value());
        }
        return array;
    }

    private JsonNode map(int n) {
        ObjectNode map = JSON.objectNode();
        for (int i = 0; i < n; i++) {
            String key = value().asText();
            map.set(key, value());
        }
        return map;
    }
}
