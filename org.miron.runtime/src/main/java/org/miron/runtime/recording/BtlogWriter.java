package org.miron.runtime.recording;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import org.miron.executor.Node;
import org.miron.executor.NodeStatus;
import org.miron.executor.Tree;
import org.miron.executor.trace.StatusListener;
import org.miron.runtime.groot.GrootTree;
import org.miron.runtime.groot.GrootTreeXml;

/**
 * Records a running tree of the Java executor as BehaviorTree.CPP's FileLogger2 does ({@link Btlog}):
 * the header when created, then every status change, those back to IDLE included (the library
 * enables them), each written to the file as it happens so that a killed process leaves every
 * transition but the one being written. The library writes from a thread every 10 ms instead;
 * a transition is 9 bytes, the tick thread can afford the write.
 */
public final class BtlogWriter implements StatusListener, AutoCloseable {
    private final Tree tree;
    private final GrootTree numbering;
    private final FileChannel file;
    private final long startNanos;
    private final ByteBuffer transition = ByteBuffer.allocate(Btlog.TRANSITION_BYTES).order(ByteOrder.LITTLE_ENDIAN);
    private boolean failed;

    private BtlogWriter(Tree tree, Path path, Path treeFile) throws IOException {
        Btlog.checkExtension(path);
        this.tree = tree;
        numbering = new GrootTree(tree);
        byte[] xml = GrootTreeXml.write(numbering, treeFile).getBytes(StandardCharsets.UTF_8);
        file = FileChannel.open(path, StandardOpenOption.CREATE, StandardOpenOption.TRUNCATE_EXISTING, StandardOpenOption.WRITE);
        ByteBuffer header = ByteBuffer.allocate(Btlog.MAGIC.length + 1 + 4 + xml.length + 8).order(ByteOrder.LITTLE_ENDIAN);
        header.put(Btlog.MAGIC).put((byte) Btlog.PROTOCOL).putInt(xml.length).put(xml);
        header.putLong(ChronoUnit.MICROS.between(Instant.EPOCH, Instant.now()));
        startNanos = System.nanoTime();
        header.flip();
        writeFully(header);
        tree.addListener(this);
    }

    /**
     * Starts recording {@code tree} into {@code path} (a .btlog), the application's node models as
     * {@code treeFile} declares them (null: none); attach before the tree runs.
     */
    public static BtlogWriter start(Tree tree, Path path, Path treeFile) throws IOException {
        return new BtlogWriter(tree, path, treeFile);
    }

    @Override
    public synchronized void statusChanged(long timeMillis, Node node, NodeStatus from, NodeStatus to) {
        int uid = numbering.uid(node);
        if (uid == 0 || failed || !file.isOpen()) {
            return;
        }
        long micros = (System.nanoTime() - startNanos) / 1000;
        transition.clear();
        transition.putLong(micros); // its low 6 bytes; the next put overwrites the other 2
        transition.position(6);
        transition.putShort((short) uid);
        // our NodeStatus is declared in BT.CPP's order: IDLE 0, RUNNING 1, SUCCESS 2, FAILURE 3, SKIPPED 4
        transition.put((byte) to.ordinal());
        transition.flip();
        try {
            writeFully(transition);
        } catch (IOException e) {
            failed = true; // a full disk must not stop the robot: say it once, record no more
            tree.context().reportProblem("recording stopped: " + e.getMessage());
        }
    }

    private void writeFully(ByteBuffer buffer) throws IOException {
        while (buffer.hasRemaining()) {
            file.write(buffer);
        }
    }

    @Override
    public synchronized void close() {
        tree.context().removeListener(this);
        try {
            file.close();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
