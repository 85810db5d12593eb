package org.miron.dds.types;

import com.fasterxml.jackson.databind.JsonNode;
import java.math.BigInteger;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;

/**
 * Writes a message (a JSON tree, field names as in its definition) as ROS 2's DDS layers write it:
 * plain CDR, XCDR1, little endian, encapsulation {@code 0x0001}, each value aligned to its size
 * from the start of the payload after the 4-byte encapsulation header. A field the tree lacks is
 * written as its default. A value that does not fit its field (text for a number, 300 for a uint8, a
 * string or array past its bound) is an {@link IllegalArgumentException} naming the field.
 */
public final class CdrWriter {
    private final TypeRegistry types;
    private ByteBuffer buf = ByteBuffer.allocate(256).order(ByteOrder.LITTLE_ENDIAN);

    private CdrWriter(TypeRegistry types) {
        this.types = types;
    }

    /** The serialized payload, encapsulation header included. */
    public static byte[] write(TypeRegistry types, MsgType type, JsonNode message) {
        CdrWriter w = new CdrWriter(types);
        w.buf.put((byte) 0).put((byte) 1).put((byte) 0).put((byte) 0); // CDR_LE, no options
        w.struct(type, message, "");
        byte[] out = new byte[w.buf.position()];
        w.buf.flip().get(out);
        return out;
    }

    private void struct(MsgType t, JsonNode m, String path) {
        if (t.fields().isEmpty()) {
            room(1).put((byte) 0); // rosidl's structure_needs_at_least_one_member
            return;
        }
        for (MsgField f : t.fields()) {
            JsonNode v = m == null ? null : m.get(f.name());
            if (v == null || v.isNull()) {
                v = f.defaultValue() != null ? f.defaultValue() : null;
            }
            field(f.type(), v, path + f.name());
        }
    }

    private void field(FieldType ft, JsonNode v, String path) {
        if (!ft.isArray()) {
            element(ft, v, path);
            return;
        }
        int n = v == null ? 0 : v.size();
        if (v != null && !v.isArray()) {
            throw new IllegalArgumentException(path + " is an array (" + ft + "), not " + v);
        }
        switch (ft.array()) {
            case FIXED -> {
                if (v != null && n != ft.size()) {
                    throw new IllegalArgumentException(path + " holds exactly " + ft.size() + " elements, got " + n);
                }
                for (int i = 0; i < ft.size(); i++) {
                    element(ft.element(), v == null ? null : v.get(i), path + "[" + i + "]");
                }
                return;
            }
            case BOUNDED -> {
                if (n > ft.size()) {
                    throw new IllegalArgumentException(path + " holds at most " + ft.size() + " elements, got " + n);
                }
            }
            default -> {
            }
        }
        align(4).putInt(n);
        for (int i = 0; i < n; i++) {
            element(ft.element(), v.get(i), path + "[" + i + "]");
        }
    }

    private void element(FieldType ft, JsonNode v, String path) {
        if (ft.primitive() == null) {
            if (v != null && !v.isObject()) {
                throw new IllegalArgumentException(path + " is a " + ft.message() + ", not " + v);
            }
            struct(types.get(ft.message()), v, path + ".");
            return;
        }
        Primitive p = ft.primitive();
        if (p.isString()) {
            String s = v == null ? "" : v.isTextual() ? v.asText() : null;
            if (s == null) {
                throw new IllegalArgumentException(path + " is a string, not " + v);
            }
            if (ft.stringBound() >= 0 && s.length() > ft.stringBound()) {
                throw new IllegalArgumentException(path + " holds at most " + ft.stringBound() + " characters, got " + s.length());
            }
            if (p == Primitive.STRING) {
                byte[] b = s.getBytes(StandardCharsets.UTF_8);
                align(4).putInt(b.length + 1);
                room(b.length + 1).put(b).put((byte) 0);
            } else { // as rmw_cyclonedds: the count of UTF-16 code units, then the units, no terminator
                align(4).putInt(s.length());
                ByteBuffer r = room(2 * s.length());
                for (char c : s.toCharArray()) {
                    r.putChar(c);
                }
            }
            return;
        }
        if (p == Primitive.BOOL) {
            if (v != null && !v.isBoolean()) {
                throw new IllegalArgumentException(path + " is a bool, not " + v);
            }
            room(1).put((byte) (v != null && v.asBoolean() ? 1 : 0));
            return;
        }
        if (v != null && !v.isNumber()) {
            throw new IllegalArgumentException(path + " is a " + p.msgName() + ", not " + v);
        }
        if (p.isFloat()) {
            double d = v == null ? 0 : v.asDouble();
            if (p == Primitive.FLOAT32) {
                align(4).putFloat((float) d);
            } else {
                align(8).putDouble(d);
            }
            return;
        }
        if (v != null && !v.isIntegralNumber() && v.asDouble() != Math.rint(v.asDouble())) {
            throw new IllegalArgumentException(path + " is a " + p.msgName() + ", not " + v);
        }
        BigInteger i = v == null ? BigInteger.ZERO : v.isIntegralNumber() ? v.bigIntegerValue() : BigInteger.valueOf((long) v.asDouble());
        try {
            Values.scalar(p, -1, i.toString()); // the range check
        } catch (Values.Bad e) {
            throw new IllegalArgumentException(path + ": " + e.getMessage());
        }
        switch (p.size) {
            case 1 -> room(1).put(i.byteValue());
            case 2 -> align(2).putShort(i.shortValue());
            case 4 -> align(4).putInt(i.intValue());
            default -> align(8).putLong(i.longValue());
        }
    }

    /** Pads to the alignment (from the payload's start after the header) and leaves room for one value of that size. */
    private ByteBuffer align(int n) {
        int pad = (n - (buf.position() - 4) % n) % n;
        room(pad + n);
        for (int i = 0; i < pad; i++) {
            buf.put((byte) 0);
        }
        return buf;
    }

    private ByteBuffer room(int n) {
        if (buf.remaining() < n) {
            ByteBuffer bigger = ByteBuffer.allocate(Math.max(buf.capacity() * 2, buf.position() + n)).order(ByteOrder.LITTLE_ENDIAN);
            buf.flip();
            bigger.put(buf);
            buf = bigger;
        }
        return buf;
    }
}
