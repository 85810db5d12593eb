package org.miron.dds.transport;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import us.ihmc.idl.IDLSequence;
import us.ihmc.idl.InterchangeSerializer;
import us.ihmc.pubsub.TopicDataType;

/**
 * Turns a message of the IHMC library into a JSON tree through the generic serializer every
 * generated type implements: one field per IDL member, by its IDL name ({@code percentage},
 * {@code header.stamp.sec}). Floats are written as their shortest decimal ({@code 0.2f} stays
 * 0.2, not 0.20000000298). Write-only.
 */
final class JsonOut implements InterchangeSerializer {
    private static final JsonNodeFactory F = JsonNodeFactory.instance;
    final ObjectNode node = F.objectNode();

    static <T> ObjectNode of(TopicDataType<T> type, T message) {
        JsonOut out = new JsonOut();
        type.serialize(message, out);
        return out.node;
    }

    static double decimal(float f) {
        return Float.isFinite(f) ? Double.parseDouble(Float.toString(f)) : f;
    }

    @Override
    public void write_type_1(String name, short v) {
        node.put(name, v);
    }

    @Override
    public void write_type_2(String name, int v) {
        node.put(name, v);
    }

    @Override
    public void write_type_3(String name, int v) {
        node.put(name, v);
    }

    @Override
    public void write_type_4(String name, long v) {
        node.put(name, v);
    }

    @Override
    public void write_type_5(String name, float v) {
        node.put(name, decimal(v));
    }

    @Override
    public void write_type_6(String name, double v) {
        node.put(name, v);
    }

    @Override
    public void write_type_7(String name, boolean v) {
        node.put(name, v);
    }

    @Override
    public void write_type_8(String name, char v) {
        node.put(name, String.valueOf(v));
    }

    @Override
    public void write_type_9(String name, byte v) {
        node.put(name, v);
    }

    @Override
    public <T> void write_type_a(String name, TopicDataType<T> type, T v) {
        node.set(name, of(type, v));
    }

    @Override
    public void write_type_c(String name, Enum<?> v) {
        node.put(name, v == null ? null : v.name());
    }

    @Override
    public void write_type_d(String name, StringBuilder v) {
        node.put(name, v.toString());
    }

    @Override
    @SuppressWarnings({"unchecked", "rawtypes"})
    public void write_type_e(String name, IDLSequence seq) {
        ArrayNode a = node.putArray(name);
        if (seq instanceof IDLSequence.Double s) {
            for (int i = 0; i < s.size(); i++) a.add(s.get(i));
        } else if (seq instanceof IDLSequence.Float s) {
            for (int i = 0; i < s.size(); i++) a.add(decimal(s.get(i)));
        } else if (seq instanceof IDLSequence.Long s) {
            for (int i = 0; i < s.size(); i++) a.add(s.get(i));
        } else if (seq instanceof IDLSequence.Integer s) {
            for (int i = 0; i < s.size(); i++) a.add(s.get(i));
        } else if (seq instanceof IDLSequence.Short s) {
            for (int i = 0; i < s.size(); i++) a.add(s.get(i));
        } else if (seq instanceof IDLSequence.Boolean s) {
            for (int i = 0; i < s.size(); i++) a.add(s.getBoolean(i));
        } else if (seq instanceof IDLSequence.Byte s) {
            for (int i = 0; i < s.size(); i++) a.add(s.get(i));
        } else if (seq instanceof IDLSequence.Char s) {
            for (int i = 0; i < s.size(); i++) a.add(String.valueOf(s.get(i)));
        } else if (seq instanceof IDLSequence.StringBuilderHolder s) {
            for (int i = 0; i < s.size(); i++) a.add(s.get(i).toString());
        } else if (seq instanceof IDLSequence.Object s) {
            for (int i = 0; i < s.size(); i++) a.add(of(s.getTopicDataType(), s.get(i)));
        } else if (seq instanceof IDLSequence.Enum s) {
            for (int i = 0; i < s.size(); i++) a.add(String.valueOf(s.get(i)));
        }
    }

    @Override
    @SuppressWarnings({"unchecked", "rawtypes"})
    public <T> void write_type_f(String name, TopicDataType<T> type, Object[] v) {
        ArrayNode a = node.putArray(name);
        for (Object o : v) a.add(of((TopicDataType) type, o));
    }

    @Override
    public <T> void write_type_f(String name, T[] v) {
        ArrayNode a = node.putArray(name);
        for (T o : v) a.add(String.valueOf(o));
    }

    @Override
    public void write_type_f(String name, boolean[] v) {
        ArrayNode a = node.putArray(name);
        for (boolean x : v) a.add(x);
    }

    @Override
    public void write_type_f(String name, byte[] v) {
        ArrayNode a = node.putArray(name);
        for (byte x : v) a.add(x);
    }

    @Override
    public void write_type_f(String name, char[] v) {
        ArrayNode a = node.putArray(name);
        for (char x : v) a.add(String.valueOf(x));
    }

    @Override
    public void write_type_f(String name, short[] v) {
        ArrayNode a = node.putArray(name);
        for (short x : v) a.add(x);
    }

    @Override
    public void write_type_f(String name, int[] v) {
        ArrayNode a = node.putArray(name);
        for (int x : v) a.add(x);
    }

    @Override
    public void write_type_f(String name, long[] v) {
        ArrayNode a = node.putArray(name);
        for (long x : v) a.add(x);
    }

    @Override
    public void write_type_f(String name, float[] v) {
        ArrayNode a = node.putArray(name);
        for (float x : v) a.add(decimal(x));
    }

    @Override
    public void write_type_f(String name, double[] v) {
        ArrayNode a = node.putArray(name);
        for (double x : v) a.add(x);
    }

    @Override
    public void write_type_11(String name, long v) {
        node.put(name, v);
    }

    @Override
    public void write_type_14(String name, char v) {
        node.put(name, String.valueOf(v));
    }

    @Override
    public void write_type_15(String name, StringBuilder v) {
        node.put(name, v.toString());
    }

    // write-only: the read side is JsonIn

    @Override
    public short read_type_1(String name) {
        throw new UnsupportedOperationException();
    }

    @Override
    public int read_type_2(String name) {
        throw new UnsupportedOperationException();
    }

    @Override
    public float read_type_5(String name) {
        throw new UnsupportedOperationException();
    }

    @Override
    public double read_type_6(String name) {
        throw new UnsupportedOperationException();
    }

    @Override
    public boolean read_type_7(String name) {
        throw new UnsupportedOperationException();
    }

    @Override
    public char read_type_8(String name) {
        throw new UnsupportedOperationException();
    }

    @Override
    public byte read_type_9(String name) {
        throw new UnsupportedOperationException();
    }

    @Override
    public <T> void read_type_a(String name, TopicDataType<T> type, T data) {
        throw new UnsupportedOperationException();
    }

    @Override
    public Enum<?> read_type_c(String name, Class<? extends Enum<?>> enumType) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void read_type_d(String name, StringBuilder res) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void read_type_e(String name, IDLSequence seq) {
        throw new UnsupportedOperationException();
    }

    @Override
    public <T> void read_type_f(String name, TopicDataType<T> type, Object[] arr) {
        throw new UnsupportedOperationException();
    }

    @Override
    public <T> void read_type_f(String name, T[] arr) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void read_type_f(String name, boolean[] arr) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void read_type_f(String name, byte[] arr) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void read_type_f(String name, char[] arr) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void read_type_f(String name, short[] arr) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void read_type_f(String name, int[] arr) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void read_type_f(String name, long[] arr) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void read_type_f(String name, float[] arr) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void read_type_f(String name, double[] arr) {
        throw new UnsupportedOperationException();
    }

    @Override
    public long read_type_11(String name) {
        throw new UnsupportedOperationException();
    }

    @Override
    public char read_type_14(String name) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void read_type_15(String name, StringBuilder res) {
        throw new UnsupportedOperationException();
    }
}
