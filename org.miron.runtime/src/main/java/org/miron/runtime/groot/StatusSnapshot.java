package org.miron.runtime.groot;

import java.io.ByteArrayOutputStream;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.ArrayDeque;
import java.util.IdentityHashMap;
import java.util.Map;
import org.miron.executor.Node;
import org.miron.executor.NodeStatus;
import org.miron.executor.trace.StatusListener;

/**
 * The STATUS reply and the recorded transitions, kept up to date from the tree's status changes. The
 * snapshot is 3 bytes a node (uid, little-endian 16 bits, then the status), subtree after subtree
 * in the order {@link GrootTree#subtrees()} lists them, as the library packs it. A node back to
 * IDLE shows 10 + the status it left, so Groot2 can still colour what it did.
 */
public final class StatusSnapshot implements StatusListener {
    /** The library keeps the last 1000 transitions. */
    static final int MAX_TRANSITIONS = 1000;

    private final GrootTree tree;
    private final byte[] buffer;
    private final Map<Node, Integer> statusOffset = new IdentityHashMap<>();
    private final ArrayDeque<long[]> transitions = new ArrayDeque<>();
    private boolean recording;
    private long recordingStartNanos;

    public StatusSnapshot(GrootTree tree) {
        this.tree = tree;
        buffer = new byte[3 * tree.size()];
        int offset = 0;
        for (GrootTree.Subtree subtree : tree.subtrees()) {
            for (Node node : subtree.nodes()) {
                int uid = tree.uid(node);
                buffer[offset] = (byte) uid;
                buffer[offset + 1] = (byte) (uid >> 8);
                statusOffset.put(node, offset + 2);
                buffer[offset + 2] = (byte) NodeStatus.IDLE.ordinal();
                offset += 3;
            }
        }
    }

    @Override
    public synchronized void statusChanged(long timeMillis, Node node, NodeStatus from, NodeStatus to) {
        Integer offset = statusOffset.get(node);
        if (offset == null) {
            return;
        }
        // our NodeStatus is declared in BT.CPP's order: IDLE 0, RUNNING 1, SUCCESS 2, FAILURE 3, SKIPPED 4
        buffer[offset] = (byte) (to == NodeStatus.IDLE ? 10 + from.ordinal() : to.ordinal());
        if (recording) {
            transitions.addLast(new long[] { (System.nanoTime() - recordingStartNanos) / 1000, tree.uid(node), to.ordinal() });
            while (transitions.size() > MAX_TRANSITIONS) {
                transitions.removeFirst();
            }
        }
    }

    public synchronized byte[] snapshot() {
        return buffer.clone();
    }

    /** Starts recording afresh; returns the wall clock in microseconds, which the library sends Groot2. */
    public synchronized long startRecording() {
        recording = true;
        recordingStartNanos = System.nanoTime();
        transitions.clear();
        return ChronoUnit.MICROS.between(Instant.EPOCH, Instant.now());
    }

    public synchronized void stopRecording() {
        recording = false;
    }

    /**
     * The transitions since the last call, then forgotten: 9 bytes each, microseconds since the
     * recording started (the low 6 bytes), uid (2 bytes), new status (1 byte), little-endian.
     */
    public synchronized byte[] takeTransitions() {
        ByteArrayOutputStream out = new ByteArrayOutputStream(9 * transitions.size());
        for (long[] t : transitions) {
            for (int i = 0; i < 6; i++) {
                out.write((int) (t[0] >> (8 * i)));
            }
            out.write((int) t[1]);
            out.write((int) (t[1] >> 8));
            out.write((int) t[2]);
        }
        transitions.clear();
        return out.toByteArray();
    }
}
