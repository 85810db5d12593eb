package org.miron.runtime.groot;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.concurrent.ThreadLocalRandom;

/**
 * Groot2's message headers (BT.CPP's groot2_protocol.h, protocol 2). A request's first part is 6
 * bytes: protocol, request type, a 32-bit unique id (little-endian, the byte order of the hosts
 * BT.CPP runs on); a reply's first part repeats them and adds the tree's 16-byte id.
 */
public final class GrootProtocol {
    public static final byte PROTOCOL_ID = 2;
    public static final int REQUEST_HEADER_SIZE = 6;
    public static final int REPLY_HEADER_SIZE = REQUEST_HEADER_SIZE + 16;

    public static final byte FULLTREE = 'T';
    public static final byte STATUS = 'S';
    public static final byte BLACKBOARD = 'B';
    public static final byte HOOK_INSERT = 'I';
    public static final byte HOOK_REMOVE = 'R';
    public static final byte BREAKPOINT_REACHED = 'N';
    public static final byte BREAKPOINT_UNLOCK = 'U';
    public static final byte HOOKS_DUMP = 'D';
    public static final byte REMOVE_ALL_HOOKS = 'A';
    public static final byte DISABLE_ALL_HOOKS = 'X';
    public static final byte TOGGLE_RECORDING = 'r';
    public static final byte GET_TRANSITIONS = 't';

    private GrootProtocol() {
    }

    /** A request header as read: the library reads any protocol byte and replies with its own. */
    public record Header(byte protocol, byte type, int uniqueId) {
        /** Null unless exactly 6 bytes (the library answers "wrong request header"). */
        public static Header parse(byte[] part) {
            if (part == null || part.length != REQUEST_HEADER_SIZE) {
                return null;
            }
            ByteBuffer in = ByteBuffer.wrap(part).order(ByteOrder.LITTLE_ENDIAN);
            return new Header(in.get(), in.get(), in.getInt());
        }

        public byte[] bytes() {
            return ByteBuffer.allocate(REQUEST_HEADER_SIZE).order(ByteOrder.LITTLE_ENDIAN)
                    .put(protocol).put(type).putInt(uniqueId).array();
        }

        /** The reply's first part: this header with our protocol id, then the tree id. */
        public byte[] reply(byte[] treeId) {
            return ByteBuffer.allocate(REPLY_HEADER_SIZE).order(ByteOrder.LITTLE_ENDIAN)
                    .put(PROTOCOL_ID).put(type).putInt(uniqueId).put(treeId, 0, 16).array();
        }
    }

    /** A header the server sends on its own (BREAKPOINT_REACHED), with a random unique id as the library's. */
    public static Header notice(byte type) {
        return new Header(PROTOCOL_ID, type, ThreadLocalRandom.current().nextInt());
    }

    /**
     * The tree id of every reply. The library draws it from a std::mt19937 it never seeds, so every
     * BT.CPP process sends the same id: the generator's first four outputs with the UUID version and
     * variant bits masked as the library masks them. We send that id too.
     */
    public static byte[] treeId() {
        long[] firstOutputs = { 3499211612L, 581869302L, 3890346734L, 3586334585L };
        ByteBuffer id = ByteBuffer.allocate(16).order(ByteOrder.LITTLE_ENDIAN);
        for (long output : firstOutputs) {
            id.putInt((int) output);
        }
        byte[] bytes = id.array();
        bytes[8] = (byte) ((bytes[8] & 0xBF) | 0x80);
        bytes[6] = (byte) ((bytes[6] & 0x4F) | 0x40);
        return bytes;
    }
}
