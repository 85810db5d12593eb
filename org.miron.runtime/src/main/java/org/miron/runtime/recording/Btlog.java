package org.miron.runtime.recording;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

/**
 * The layout of BehaviorTree.CPP 4's FileLogger2 recordings (src/loggers/bt_file_logger_v2.cpp,
 * not its header's comment, which leaves out the first two fields): the 18 bytes
 * {@code BTCPP4-FileLogger2}, the protocol byte 1, the length of the tree XML (int32), the XML
 * (the tree as Groot2's FULLTREE sends it, with {@code _uid}s), the first timestamp (int64,
 * microseconds since the epoch), then 9 bytes per transition: microseconds since the first
 * timestamp (its low 6 bytes), the node's uid (2 bytes), its new status (1 byte, BT.CPP's
 * NodeStatus value). Every number little-endian.
 */
public final class Btlog {
    public static final byte[] MAGIC = "BTCPP4-FileLogger2".getBytes(StandardCharsets.US_ASCII);
    public static final int PROTOCOL = 1;
    public static final int TRANSITION_BYTES = 9;
    public static final String EXTENSION = ".btlog";
    /** What the bus log beside {@code run.btlog} is called: {@code run.bus.jsonl}. */
    public static final String BUS_LOG_SUFFIX = ".bus.jsonl";

    private Btlog() {
    }

    /** The bus log beside a recording: {@code run.btlog} → {@code run.bus.jsonl}. */
    public static Path busLogOf(Path btlog) {
        String name = btlog.getFileName().toString();
        String stem = name.endsWith(EXTENSION) ? name.substring(0, name.length() - EXTENSION.length()) : name;
        return btlog.resolveSibling(stem + BUS_LOG_SUFFIX);
    }

    /** FileLogger2 refuses another extension (Groot2 opens only .btlog): so do we, with the library's reason. */
    public static void checkExtension(Path file) {
        if (!file.getFileName().toString().endsWith(EXTENSION)) {
            throw new IllegalArgumentException(file + ": a recording's file name must end with " + EXTENSION
                    + " (FileLogger2 and Groot2 require it)");
        }
    }
}
