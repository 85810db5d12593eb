package org.miron.runtime.groot;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.Iterator;
import java.util.Map;

/**
 * JSON to MessagePack, the encoding of the BLACKBOARD reply, with the choices nlohmann::json's
 * to_msgpack makes: the shortest integer form, reals as float64, object keys as the JSON holds them.
 */
public final class MsgPack {
    private final ByteArrayOutputStream out = new ByteArrayOutputStream();

    private MsgPack() {
    }

    public static byte[] encode(JsonNode json) {
        MsgPack pack = new MsgPack();
        pack.write(json);
        return pack.out.toByteArray();
    }

    private void write(JsonNode json) {
        if (json == null || json.isNull() || json.isMissingNode()) {
            out.write(0xC0);
        } else if (json.isBoolean()) {
            out.write(json.booleanValue() ? 0xC3 : 0xC2);
        } else if (json.isIntegralNumber() && json.canConvertToLong()) {
            integer(json.longValue());
        } else if (json.isNumber()) {
            out.write(0xCB);
            bigEndian(Double.doubleToLongBits(json.doubleValue()), 8);
        } else if (json.isTextual()) {
            text(json.textValue());
        } else if (json.isArray()) {
            header(json.size(), 0x90, 16, 0xDC, 0xDD);
            json.forEach(this::write);
        } else if (json.isObject()) {
            header(json.size(), 0x80, 16, 0xDE, 0xDF);
            for (Iterator<Map.Entry<String, JsonNode>> it = json.fields(); it.hasNext();) {
                Map.Entry<String, JsonNode> field = it.next();
                text(field.getKey());
                write(field.getValue());
            }
        } else {
            text(json.asText());
        }
    }

    private void integer(long v) {
        if (v >= 0) {
            if (v < 128) {
                out.write((int) v);
            } else if (v <= 0xFF) {
                out.write(0xCC);
                bigEndian(v, 1);
            } else if (v <= 0xFFFF) {
                out.write(0xCD);
                bigEndian(v, 2);
            } else if (v <= 0xFFFFFFFFL) {
                out.write(0xCE);
                bigEndian(v, 4);
            } else {
                out.write(0xCF);
                bigEndian(v, 8);
            }
        } else if (v >= -32) {
            out.write((int) (v & 0xFF));
        } else if (v >= Byte.MIN_VALUE) {
            out.write(0xD0);
            bigEndian(v, 1);
        } else if (v >= Short.MIN_VALUE) {
            out.write(0xD1);
            bigEndian(v, 2);
        } else if (v >= Integer.MIN_VALUE) {
            out.write(0xD2);
            bigEndian(v, 4);
        } else {
            out.write(0xD3);
            bigEndian(v, 8);
        }
    }

    private void text(String s) {
        byte[] utf8 = s.getBytes(StandardCharsets.UTF_8);
        int n = utf8.length;
        if (n < 32) {
            out.write(0xA0 | n);
        } else if (n <= 0xFF) {
            out.write(0xD9);
            bigEndian(n, 1);
        } else if (n <= 0xFFFF) {
            out.write(0xDA);
            bigEndian(n, 2);
        } else {
            out.write(0xDB);
            bigEndian(n, 4);
        }
        out.write(utf8, 0, n);
    }

    private void header(int n, int fix, int fixLimit, int sixteen, int thirtyTwo) {
        if (n < fixLimit) {
            out.write(fix | n);
        } else if (n <= 0xFFFF) {
            out.write(sixteen);
            bigEndian(n, 2);
        } else {
            out.write(thirtyTwo);
            bigEndian(n, 4);
        }
    }

    private void bigEndian(long v, int bytes) {
        for (int i = bytes - 1; i >= 0; i--) {
            out.write((int) (v >> (8 * i)));
        }
    }
}
