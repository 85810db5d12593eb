package org.miron.dds.transport;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.MissingNode;
import us.ihmc.idl.IDLSequence;
import us.ihmc.idl.InterchangeSerializer;
import us.ihmc.pubsub.TopicDataType;

/**
 * Fills a message of the IHMC library from a JSON tree, the reverse of {@link JsonOut}: a member
 * the tree does not name keeps its IDL default (0, false, "", empty), so the bridge writes only
 * the fields it maps ({@code data} of a {@code std_msgs/String}). Fixed-size arrays and sequences of
 * structs are left at their defaults: nothing the bridge writes has them. Read-only.
 */
final class JsonIn implements InterchangeSerializer {
    private final JsonNode node;

    JsonIn(JsonNode node) {
        this.node = node == null ? MissingNode.getInstance() : node;
    }

    static <T> T fill(TopicDataType<T> type, JsonNode json) {
        T message = type.createData();
        type.deserialize(new JsonIn(json), message);
        return message;
    }

    private JsonNode at(String name) {
        return node.path(name);
    }

    @Override
    public short read_type_1(String name) {
        return (short) at(name).asInt();
    }

    @Override
    public int read_type_2(String name) {
        return at(name).asInt();
    }

    @Override
    public int read_type_3(String name) {
        return at(name).asInt();
    }

    @Override
    public long read_type_4(String name) {
        return at(name).asLong();
    }

    @Override
    public float read_type_5(String name) {
        return (float) at(name).asDouble();
    }

    @Override
    public double read_type_6(String name) {
        return at(name).asDouble();
    }

    @Override
    public boolean read_type_7(String name) {
        return at(name).asBoolean();
    }

    @Override
    public char read_type_8(String name) {
        String s = at(name).asText();
        return s.isEmpty() ? '\0' : s.charAt(0);
    }

    @Override
    public byte read_type_9(String name) {
        return (byte) at(name).asInt();
    }

    @Override
    public <T> void read_type_a(String name, TopicDataType<T> type, T data) {
        type.deserialize(new JsonIn(at(name)), data);
    }

    @Override
    public Enum<?> read_type_c(String name, Class<? extends Enum<?>> enumType) {
        for (Enum<?> e : enumType.getEnumConstants()) {
            if (e.name().equals(at(name).asText())) {
                return e;
            }
        }
        return enumType.getEnumConstants()[0];
    }

    @Override
    public void read_type_d(String name, StringBuilder res) {
        res.setLength(0);
        if (at(name).isValueNode()) {
            res.append(at(name).asText());
        }
    }

    @Override
    public void read_type_e(String name, IDLSequence seq) {
        seq.resetQuick();
        JsonNode a = at(name);
        for (int i = 0; i < a.size(); i++) {
            JsonNode v = a.get(i);
            if (seq instanceof IDLSequence.Double s) {
                s.add(v.asDouble());
            } else if (seq instanceof IDLSequence.Float s) {
                s.add((float) v.asDouble());
            } else if (seq instanceof IDLSequence.Long s) {
                s.add(v.asLong());
            } else if (seq instanceof IDLSequence.Integer s) {
                s.add(v.asInt());
            } else if (seq instanceof IDLSequence.Boolean s) {
                s.add(v.asBoolean());
            } else if (seq instanceof IDLSequence.StringBuilderHolder s) {
                s.add(v.asText());
            }
        }
    }

    @Override
    public <T> void read_type_f(String name, TopicDataType<T> type, Object[] arr) {
    }

    @Override
    public <T> void read_type_f(String name, T[] arr) {
    }

    @Override
    public void read_type_f(String name, boolean[] arr) {
    }

    @Override
    public void read_type_f(String name, byte[] arr) {
    }

    @Override
    public void read_type_f(String name, char[] arr) {
    }

    @Override
    public void read_type_f(String name, short[] arr) {
    }

    @Override
    public void read_type_f(String name, int[] arr) {
    }

    @Override
    public void read_type_f(String name, long[] arr) {
    }

    @Override
    public void read_type_f(String name, float[] arr) {
    }

    @Override
    public void read_type_f(String name, double[] arr) {
        for (int i = 0; i < arr.length && i < at(name).size(); i++) {
            arr[i] = at(name).get(i).asDouble();
        }
    }

    @Override
    public long read_type_11(String name) {
        return at(name).asLong();
    }

    @Override
    public char read_type_14(String name) {
        return read_type_8(name);
    }

    @Override
    public void read_type_15(String name, StringBuilder res) {
        read_type_d(name, res);
    }

    // read-only: the write side is JsonOut

    @Override
    public void write_type_1(String name, short v) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void write_type_2(String name, int v) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void write_type_5(String name, float v) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void write_type_6(String name, double v) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void write_type_7(String name, boolean v) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void write_type_8(String name, char v) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void write_type_9(String name, byte v) {
        throw new UnsupportedOperationException();
    }

    @Override
    public <T> void write_type_a(String name, TopicDataType<T> type, T data) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void write_type_c(String name, Enum<?> v) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void write_type_d(String name, StringBuilder v) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void write_type_e(String name, IDLSequence seq) {
        throw new UnsupportedOperationException();
    }

    @Override
    public <T> void write_type_f(String name, TopicDataType<T> type, Object[] v) {
        throw new UnsupportedOperationException();
    }

    @Override
    public <T> void write_type_f(String name, T[] v) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void write_type_f(String name, boolean[] v) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void write_type_f(String name, byte[] v) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void write_type_f(String name, char[] v) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void write_type_f(String name, short[] v) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void write_type_f(String name, int[] v) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void write_type_f(String name, long[] v) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void write_type_f(String name, float[] v) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void write_type_f(String name, double[] v) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void write_type_11(String name, long v) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void write_type_14(String name, char v) {
        throw new UnsupportedOperationException();
    }

    @Override
    public void write_type_15(String name, StringBuilder v) {
        throw new UnsupportedOperationException();
    }
}
