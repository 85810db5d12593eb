package org.miron.dds.types;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.math.BigInteger;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;

/**
 * Reads a serialized payload of a defined type into a JSON tree. The encapsulation header says
 * how: XCDR1 plain CDR ({@code 0x0000}/{@code 0x0001}, alignment to the value's size), XCDR2 plain
 * ({@code 0x0006}/{@code 0x0007}: alignment at most 4, a DHEADER before arrays and sequences of
 * strings or structs) or XCDR2 delimited ({@code 0x0008}/{@code 0x0009}: a DHEADER before every
 * struct too, as for appendable types); either byte order. Anything else, or a payload that ends
 * early or breaks a bound, is an {@link Undecodable}.
 */
public final class CdrReader {
    /** A payload that is not a message of the type. */
    public static final class Undecodable extends Exception {
        private static final long serialVersionUID = 1L;

        Undecodable(String why) {
            super(why);
        }
    }

    private static final JsonNodeFactory F = JsonNodeFactory.instance;
    private final TypeRegistry types;
    private final ByteBuffer buf;
    private final boolean xcdr2;
    private final boolean delimited;

    private CdrReader(TypeRegistry types, ByteBuffer buf, boolean xcdr2, boolean delimited) {
        this.types = types;
        this.buf = buf;
        this.xcdr2 = xcdr2;
        this.delimited = delimited;
    }

    public static ObjectNode read(TypeRegistry types, MsgType type, byte[] payload, int length) throws Undecodable {
        if (length < 4) {
            throw new Undecodable("a payload of " + length + " bytes has no encapsulation header");
        }
        int id = ((payload[0] & 0xff) << 8) | (payload[1] & 0xff);
        boolean xcdr2;
        boolean delimited = false;
        switch (id) {
            case 0, 1 -> xcdr2 = false;
            case 6, 7 -> xcdr2 = true;
            case 8, 9 -> {
                xcdr2 = true;
                delimited = true;
            }
            default -> throw new Undecodable("encapsulation 0x" + Integer.toHexString(id)
                    + " is not plain CDR (XCDR1 0x0000/0x0001, XCDR2 0x0006 to 0x0009)");
        }
        ByteBuffer b = ByteBuffer.wrap(payload, 4, length - 4).slice().order((id & 1) == 1 ? ByteOrder.LITTLE_ENDIAN : ByteOrder.BIG_ENDIAN);
        try {
            return new CdrReader(types, b, xcdr2, delimited).struct(type, "", delimited);
        } catch (java.nio.BufferUnderflowException | IndexOutOfBoundsException e) {
            throw new Undecodable("the payload ends before the " + type.fullName() + " does (" + (length - 4) + " bytes)");
        }
    }

    /**
     * A struct, after its DHEADER when {@code delimited}. A .msg does not say whether a nested type
     * is final or appendable, so in a delimited payload a nested struct is read as appendable when
     * its DHEADER fits and the members decode within it, filling it, else again as final (no
     * DHEADER). Only the top-level struct may carry members this definition lacks.
     */
    private ObjectNode struct(MsgType t, String path, boolean withHeader) throws Undecodable {
        if (!withHeader) {
            return members(t, path);
        }
        int start = buf.position();
        int size = align(4).getInt();
        int end = buf.position() + size;
        if (size < 0 || end > buf.limit()) {
            if (delimited && !path.isEmpty()) {
                buf.position(start);
                return members(t, path);
            }
            throw new Undecodable(path + ": a struct of " + Integer.toUnsignedString(size) + " bytes past the payload's end");
        }
        int limit = buf.limit();
        buf.limit(end);
        try {
            ObjectNode o = members(t, path);
            if (!path.isEmpty() && end - buf.position() >= 4) {
                // what a DHEADER delimits, the members fill (up to padding): else that was no DHEADER
                throw new Undecodable(path + ": a struct of " + size + " bytes whose members take " + (size - (end - buf.position())));
            }
            buf.limit(limit);
            buf.position(end); // the top-level's members appended by a newer version of the type are skipped
            return o;
        } catch (Undecodable | RuntimeException e) {
            buf.limit(limit);
            if (path.isEmpty()) {
                throw e;
            }
            buf.position(start);
            return members(t, path);
        }
    }

    private ObjectNode members(MsgType t, String path) throws Undecodable {
        ObjectNode o = F.objectNode();
        if (t.fields().isEmpty()) {
            buf.get();
        }
        for (MsgField f : t.fields()) {
            o.set(f.name(), field(f.type(), path + f.name()));
        }
        return o;
    }

    private JsonNode field(FieldType ft, String path) throws Undecodable {
        if (!ft.isArray()) {
            return element(ft, path);
        }
        boolean complex = ft.primitive() == null || ft.primitive().isString();
        if (xcdr2 && complex) {
            align(4).getInt(); // DHEADER: the collection's size in bytes; the elements say as much
        }
        int n = ft.array() == FieldType.Array.FIXED ? ft.size() : align(4).getInt();
        if (n < 0 || n > buf.remaining()) {
            throw new Undecodable(path + ": " + Integer.toUnsignedString(n) + " elements cannot fit in the " + buf.remaining() + " bytes left");
        }
        if (ft.array() == FieldType.Array.BOUNDED && n > ft.size()) {
            throw new Undecodable(path + " holds at most " + ft.size() + " elements, the sample has " + n);
        }
        ArrayNode a = F.arrayNode();
        for (int i = 0; i < n; i++) {
            a.add(element(ft.element(), path + "[" + i + "]"));
        }
        return a;
    }

    private JsonNode element(FieldType ft, String path) throws Undecodable {
        if (ft.primitive() == null) {
            return struct(types.get(ft.message()), path + ".", delimited);
        }
        Primitive p = ft.primitive();
        switch (p) {
            case STRING -> {
                int len = align(4).getInt();
                if (len < 1 || len > buf.remaining()) {
                    throw new Undecodable(path + ": a string of " + Integer.toUnsignedString(len) + " bytes with " + buf.remaining() + " left");
                }
                byte[] b = new byte[len];
                buf.get(b);
                int n = b[len - 1] == 0 ? len - 1 : len;
                String s = new String(b, 0, n, StandardCharsets.UTF_8);
                return bounded(ft, s, path);
            }
            case WSTRING -> {
                int len = align(4).getInt();
                if (len < 0 || 2L * len > buf.remaining()) {
                    throw new Undecodable(path + ": a wstring of " + Integer.toUnsignedString(len) + " characters with " + buf.remaining() + " bytes left");
                }
                char[] c = new char[len];
                for (int i = 0; i < len; i++) {
                    c[i] = buf.getChar();
                }
                return bounded(ft, new String(c), path);
            }
            case BOOL -> {
                byte b = buf.get();
                if (b != 0 && b != 1) {
                    throw new Undecodable(path + ": a bool is 0 or 1, the sample has " + b);
                }
                return F.booleanNode(b == 1);
            }
            case FLOAT32 -> {
                float f = align(4).getFloat();
                return F.numberNode(Float.isFinite(f) ? Double.parseDouble(Float.toString(f)) : f);
            }
            case FLOAT64 -> {
                return F.numberNode(align(8).getDouble());
            }
            case INT8 -> {
                return F.numberNode((long) buf.get());
            }
            case BYTE, CHAR, UINT8 -> {
                return F.numberNode((long) (buf.get() & 0xff));
            }
            case INT16 -> {
                return F.numberNode((long) align(2).getShort());
            }
            case UINT16 -> {
                return F.numberNode((long) (align(2).getShort() & 0xffff));
            }
            case INT32 -> {
                return F.numberNode((long) align(4).getInt());
            }
            case UINT32 -> {
                return F.numberNode(align(4).getInt() & 0xffffffffL);
            }
            case INT64 -> {
                return F.numberNode(align(8).getLong());
            }
            default -> { // UINT64
                long v = align(8).getLong();
                return v >= 0 ? F.numberNode(v) : F.numberNode(new BigInteger(Long.toUnsignedString(v)));
            }
        }
    }

    private JsonNode bounded(FieldType ft, String s, String path) throws Undecodable {
        if (ft.stringBound() >= 0 && s.length() > ft.stringBound()) {
            throw new Undecodable(path + " holds at most " + ft.stringBound() + " characters, the sample has " + s.length());
        }
        return F.textNode(s);
    }

    private ByteBuffer align(int n) {
        int a = xcdr2 ? Math.min(n, 4) : n;
        int pad = (a - buf.position() % a) % a;
        buf.position(buf.position() + pad);
        return buf;
    }
}
