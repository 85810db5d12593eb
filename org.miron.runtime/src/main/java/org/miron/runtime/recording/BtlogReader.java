package org.miron.runtime.recording;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.miron.executor.NodeStatus;

/**
 * Reads a FileLogger2 recording ({@link Btlog}), whoever wrote it (BT.CPP's FileLogger2, our
 * {@link BtlogWriter}). A recording cut short keeps its complete transitions; a file whose header
 * is not FileLogger2's, or is incomplete, is refused with the reason.
 */
public final class BtlogReader {
    private static final int STATUSES = NodeStatus.values().length;

    private BtlogReader() {
    }

    public static Recording read(Path file) throws IOException {
        return parse(Files.readAllBytes(file), file.toString());
    }

    static Recording parse(byte[] bytes, String name) throws BtlogFormatException {
        ByteBuffer in = ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN);
        if (bytes.length < Btlog.MAGIC.length || !Arrays.equals(Arrays.copyOf(bytes, Btlog.MAGIC.length), Btlog.MAGIC)) {
            throw new BtlogFormatException(name + ": not a BehaviorTree.CPP recording (a .btlog starts with \"BTCPP4-FileLogger2\")");
        }
        in.position(Btlog.MAGIC.length);
        if (in.remaining() < 1 + 4) {
            throw new BtlogFormatException(name + ": the recording's header is cut short");
        }
        int protocol = in.get() & 0xFF;
        if (protocol != Btlog.PROTOCOL) {
            throw new BtlogFormatException(name + ": FileLogger2 protocol " + protocol + ", only " + Btlog.PROTOCOL + " is known");
        }
        int xmlLength = in.getInt();
        if (xmlLength < 0 || in.remaining() < (long) xmlLength + 8) {
            throw new BtlogFormatException(name + ": the recording's header is cut short (its tree XML is "
                    + xmlLength + " bytes, " + Math.max(0, in.remaining() - 8) + " there)");
        }
        String xml = new String(bytes, in.position(), xmlLength, StandardCharsets.UTF_8);
        in.position(in.position() + xmlLength);
        long start = in.getLong();
        List<Recording.Transition> transitions = new ArrayList<>(in.remaining() / Btlog.TRANSITION_BYTES);
        while (in.remaining() >= Btlog.TRANSITION_BYTES) {
            long micros = 0;
            for (int i = 0; i < 6; i++) {
                micros |= (long) (in.get() & 0xFF) << (8 * i);
            }
            int uid = in.getShort() & 0xFFFF;
            int status = in.get() & 0xFF;
            if (status >= STATUSES) {
                throw new BtlogFormatException(name + ": transition " + (transitions.size() + 1) + " has status "
                        + status + ", not a node status (0 to " + (STATUSES - 1) + ")");
            }
            transitions.add(new Recording.Transition(micros, uid, NodeStatus.values()[status]));
        }
        return new Recording(xml, start, List.copyOf(transitions), in.remaining());
    }
}
