package org.miron.dds.transport;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.Locale;
import us.ihmc.idl.CDR;
import us.ihmc.idl.IDLSequence;
import us.ihmc.idl.InterchangeSerializer;
import us.ihmc.pubsub.TopicDataType;
import us.ihmc.pubsub.common.SerializedPayload;

/**
 * RoQME's own DDS types (module {@code RoqmeDDSTopics} of the original IDL): the six context
 * structs {@code { string name; sequence<T> value; }}, {@code RoqmeEstimate { string name; double
 * value; }} and {@code RoqmeObservation { string name; }}. One class for all of them: they differ
 * only in the element type of {@code value}. Bounds as the IHMC generator sets them for an IDL
 * without bounds: names up to 255 characters, at most 100 values.
 *
 * <p>In the original IDL {@code name} is the key ({@code @key}); a keyed instance hands Fast-DDS the
 * RTPS key hash of each sample ({@link #getKey}), an unkeyed one (for peers that declared the
 * structs without the key) none. The two are different topics to DDS and never match each other.
 */
final class RoqmeType implements TopicDataType<RoqmeType.Message> {
    static final String MODULE = "RoqmeDDSTopics::";
    static final int MAX_VALUES = 100;

    /** The struct a topic carries, by its IDL name, and the IHMC type code of its sequence's elements. */
    enum Kind {
        INT("RoqmeIntContext", "type_11"), UINT("RoqmeUIntContext", "type_12"), DOUBLE("RoqmeDoubleContext", "type_6"),
        BOOL("RoqmeBoolContext", "type_7"), EVENT("RoqmeEventContext", "type_d"), ENUM("RoqmeEnumContext", "type_d"),
        ESTIMATE("RoqmeEstimate", null), OBSERVATION("RoqmeObservation", null);

        final String struct;
        final String code;

        Kind(String struct, String code) {
            this.struct = struct;
            this.code = code;
        }

        boolean context() {
            return code != null;
        }

        static Kind of(String struct) {
            for (Kind k : values()) {
                if (k.struct.equals(struct)) {
                    return k;
                }
            }
            return null;
        }

        IDLSequence newSequence() {
            return switch (this) {
                case INT, UINT -> new IDLSequence.Long(MAX_VALUES, code);
                case DOUBLE -> new IDLSequence.Double(MAX_VALUES, code);
                case BOOL -> new IDLSequence.Boolean(MAX_VALUES, code);
                case EVENT, ENUM -> new IDLSequence.StringBuilderHolder(MAX_VALUES, code);
                default -> null;
            };
        }

        @Override
        public String toString() {
            return struct.toLowerCase(Locale.ROOT);
        }
    }

    /** One sample: the name (the key) and the values of a context, or an estimate's value. */
    static final class Message {
        final StringBuilder name = new StringBuilder();
        final IDLSequence values;
        double value;

        Message(Kind kind) {
            this.values = kind.newSequence();
        }
    }

    private final Kind kind;
    private final boolean keyed;
    private final CDR serializeCdr = new CDR();
    private final CDR deserializeCdr = new CDR();

    RoqmeType(Kind kind, boolean keyed) {
        this.kind = kind;
        this.keyed = keyed;
    }

    boolean keyed() {
        return keyed;
    }

    /**
     * The RTPS key hash of a keyed sample: the key ({@code name}) serialized as big-endian CDR
     * (length with the terminating NUL, the bytes, the NUL), then MD5, because a string key may be
     * longer than 16 bytes (RTPS 2.3, 9.6.3.8). Nothing for an unkeyed type.
     */
    @Override
    public void getKey(Message m, ByteBuffer key) {
        if (!keyed) {
            return;
        }
        byte[] name = m.name.toString().getBytes(StandardCharsets.UTF_8);
        ByteBuffer cdr = ByteBuffer.allocate(4 + name.length + 1).putInt(name.length + 1).put(name).put((byte) 0);
        try {
            key.put(MessageDigest.getInstance("MD5").digest(cdr.array()));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("every Java platform has MD5", e);
        }
    }

    @Override
    public void serialize(Message m, SerializedPayload payload) throws IOException {
        serializeCdr.serialize(payload);
        serialize(m, serializeCdr);
        serializeCdr.finishSerialize();
    }

    @Override
    public void deserialize(SerializedPayload payload, Message m) throws IOException {
        deserializeCdr.deserialize(payload);
        deserialize(m, deserializeCdr);
        deserializeCdr.finishDeserialize();
    }

    @Override
    public void serialize(Message m, CDR cdr) {
        if (m.name.length() > 255) {
            throw new IllegalArgumentException("name exceeds the maximum length of 255");
        }
        cdr.write_type_d(m.name);
        if (kind.context()) {
            cdr.write_type_e(m.values);
        } else if (kind == Kind.ESTIMATE) {
            cdr.write_type_6(m.value);
        }
    }

    @Override
    public void deserialize(Message m, CDR cdr) {
        cdr.read_type_d(m.name);
        if (kind.context()) {
            cdr.read_type_e(m.values);
        } else if (kind == Kind.ESTIMATE) {
            m.value = cdr.read_type_6();
        }
    }

    @Override
    public void serialize(Message m, InterchangeSerializer ser) {
        ser.write_type_d("name", m.name);
        if (kind.context()) {
            ser.write_type_e("value", m.values);
        } else if (kind == Kind.ESTIMATE) {
            ser.write_type_6("value", m.value);
        }
    }

    @Override
    public void deserialize(InterchangeSerializer ser, Message m) {
        ser.read_type_d("name", m.name);
        if (kind.context()) {
            ser.read_type_e("value", m.values);
        } else if (kind == Kind.ESTIMATE) {
            m.value = ser.read_type_6("value");
        }
    }

    @Override
    public void copy(Message src, Message dest) {
        dest.name.setLength(0);
        dest.name.append(src.name);
        dest.value = src.value;
        if (kind.context()) {
            new JsonIn(JsonOut.of(this, src)).read_type_e("value", dest.values);
        }
    }

    @Override
    public int getTypeSize() {
        // name (4 + 255 + 1) and up to 100 values of at most 8 bytes, or 100 strings of 4 + 255 + 1
        return CDR.getTypeSize(4 + 256 + 8 + MAX_VALUES * 260);
    }

    @Override
    public String getName() {
        return MODULE + kind.struct;
    }

    @Override
    public Message createData() {
        return new Message(kind);
    }

    @Override
    public TopicDataType<Message> newInstance() {
        return new RoqmeType(kind, keyed);
    }
}
