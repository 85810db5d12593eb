package org.miron.dds.transport;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.ByteBuffer;
import org.miron.dds.types.CdrReader;
import org.miron.dds.types.CdrWriter;
import org.miron.dds.types.FieldType;
import org.miron.dds.types.MsgField;
import org.miron.dds.types.MsgType;
import org.miron.dds.types.TypeRegistry;
import us.ihmc.idl.CDR;
import us.ihmc.idl.InterchangeSerializer;
import us.ihmc.pubsub.TopicDataType;
import us.ihmc.pubsub.common.SerializedPayload;

/**
 * A message type read from a definition, as the DDS library wants a type: its samples are JSON
 * trees, encoded by {@link CdrWriter} (XCDR1) and decoded by {@link CdrReader} (XCDR1 or XCDR2)
 * straight into the library's payload. A sample that does not decode keeps the reason, and the
 * transport reports it instead of a message (the library would drop an exception silently).
 */
final class DefinedType implements TopicDataType<DefinedType.Sample> {
    /** Strings and sequences without a bound are sized as the library's generated types are: 255 characters, 100 elements. */
    private static final int UNBOUNDED_STRING = 255;
    private static final int UNBOUNDED_SEQUENCE = 100;
    private static final int MIN_SIZE = 8 * 1024;
    private static final int MAX_SIZE = 16 * 1024 * 1024;

    /** One sample: the message, or why the payload was not one. */
    static final class Sample {
        ObjectNode json;
        String error;
    }

    private final TypeRegistry types;
    private final MsgType type;
    private final int size;

    DefinedType(TypeRegistry types, MsgType type) {
        this.types = types;
        this.type = type;
        this.size = (int) Math.min(MAX_SIZE, Math.max(MIN_SIZE, 4 + bound(type)));
    }

    /** The most bytes a sample can take (unbounded strings and sequences as above; padding counted generously). */
    private long bound(MsgType t) {
        long n = 1;
        for (MsgField f : t.fields()) {
            FieldType ft = f.type();
            long one = ft.primitive() == null ? bound(types.get(ft.message()))
                    : ft.primitive().isString() ? 8 + 4L * (ft.stringBound() >= 0 ? ft.stringBound() : UNBOUNDED_STRING)
                    : 2L * ft.primitive().size;
            long count = switch (ft.array()) {
                case NONE -> 1;
                case FIXED, BOUNDED -> ft.size();
                case UNBOUNDED -> UNBOUNDED_SEQUENCE;
            };
            n += 8 + one * count;
        }
        return Math.min(n, MAX_SIZE);
    }

    ObjectNode template() {
        return types.template(type);
    }

    Sample fill(JsonNode message) {
        Sample s = new Sample();
        s.json = message == null ? template() : (ObjectNode) message;
        return s;
    }

    @Override
    public void serialize(Sample s, SerializedPayload payload) throws IOException {
        byte[] b = CdrWriter.write(types, type, s.json);
        if (b.length > payload.getMax_size()) {
            throw new IllegalArgumentException("a " + type.fullName() + " of " + b.length + " bytes exceeds the maximum length of "
                    + payload.getMax_size());
        }
        ByteBuffer data = payload.getData();
        data.clear();
        data.put(b);
        data.flip();
        payload.setLength(b.length);
    }

    @Override
    public void deserialize(SerializedPayload payload, Sample s) throws IOException {
        ByteBuffer data = payload.getData();
        int start = data.position();
        int length = Math.min(payload.getLength(), data.limit() - start);
        byte[] b = new byte[Math.max(0, length)];
        data.get(start, b);
        try {
            s.json = CdrReader.read(types, type, b, b.length);
            s.error = null;
        } catch (CdrReader.Undecodable e) {
            s.json = null;
            s.error = e.getMessage();
        }
    }

    @Override
    public void serialize(Sample data, InterchangeSerializer serializer) {
        throw new UnsupportedOperationException("a defined type is converted by the transport, not the library");
    }

    @Override
    public void deserialize(InterchangeSerializer serializer, Sample data) {
        throw new UnsupportedOperationException("a defined type is converted by the transport, not the library");
    }

    @Override
    public void serialize(Sample data, CDR cdr) {
        throw new UnsupportedOperationException("a defined type is serialized whole (serialize to a payload)");
    }

    @Override
    public void deserialize(Sample data, CDR cdr) {
        throw new UnsupportedOperationException("a defined type is deserialized whole (deserialize from a payload)");
    }

    @Override
    public void copy(Sample src, Sample dest) {
        dest.json = src.json == null ? null : src.json.deepCopy();
        dest.error = src.error;
    }

    @Override
    public int getTypeSize() {
        return size;
    }

    @Override
    public String getName() {
        return type.ddsName();
    }

    @Override
    public Sample createData() {
        return new Sample();
    }

    @Override
    public TopicDataType<Sample> newInstance() {
        return new DefinedType(types, type);
    }
}
