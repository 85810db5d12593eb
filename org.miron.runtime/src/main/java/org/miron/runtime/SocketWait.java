package org.miron.runtime;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.channels.ClosedSelectorException;
import java.nio.channels.SelectableChannel;
import java.nio.channels.Selector;
import java.util.concurrent.locks.LockSupport;
import org.zeromq.ZMQ;

/**
 * Waits until ZeroMQ sockets (and raw channels) may have something to read, for loops that then
 * read non-blocking until there is nothing left; replaces {@code ZMQ.Poller} in those loops.
 *
 * <p>Contract (ZeroMQ's {@code ZMQ_FD}): a socket's FD becomes readable when a command reaches its
 * mailbox, e.g. "a pipe has data again", which is sent only after a read found that pipe empty.
 * So before waiting, read every watched socket until it returns nothing, and do that after the
 * last send or subscribe on it too (they process the mailbox and may consume the notification).
 * {@code ZMQ.Poller} hides this by asking each socket for its events; a raw selector cannot.
 *
 * <p>Why not JeroMQ's poll: in JeroMQ 0.6.0 the thread that queues a command for a socket (an I/O
 * thread, or the peer's) writes the mailbox's wake-up byte before it counts it
 * ({@code Signaler.send}). The write wakes the socket's owner, and on a busy machine the writer is
 * preempted right there: the mailbox FD is readable but the socket reports no event, so
 * {@code ZMQ.poll} goes round its select loop at full speed (and reports a registered raw channel
 * ready from a stale selection key) until the writer runs again, milliseconds later on 2 shared
 * cores, while the spinning owner keeps it off the CPU. That was the ≈ 10 ms end-to-end p99
 * (docs/performance.md). Here a wake-up that finds nothing to do pauses briefly instead
 * ({@link #idle}), which gives the core to the writer.
 */
public final class SocketWait implements AutoCloseable {
    /** Pause after a wake-up with nothing to do: long enough for the preempted writer to run. */
    private static final long IDLE_PAUSE_NS = 50_000;
    private final Selector selector;

    public SocketWait() {
        try {
            selector = Selector.open();
        } catch (IOException e) {
            throw new UncheckedIOException("cannot open a selector", e);
        }
    }

    /** Watches a socket's mailbox FD (what {@code ZMQ.Poller} watches too). */
    public SocketWait add(ZMQ.Socket socket) {
        return add(socket.getFD());
    }

    /** Watches a non-blocking channel for input. */
    public SocketWait add(SelectableChannel channel) {
        try {
            channel.register(selector, java.nio.channels.SelectionKey.OP_READ);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot watch " + channel, e);
        }
        return this;
    }

    /**
     * Waits up to {@code timeoutMs} (at least 1) until a watched FD is readable; true if one is.
     * Only a hint: the caller reads non-blocking and calls {@link #idle} if there was nothing.
     */
    public boolean await(long timeoutMs) {
        try {
            int n = selector.select(Math.max(1, timeoutMs));
            selector.selectedKeys().clear();
            return n > 0;
        } catch (IOException | ClosedSelectorException e) {
            return false;
        }
    }

    /** After {@link #await} returned true but the sockets had nothing: yields the core briefly. */
    public void idle() {
        LockSupport.parkNanos(IDLE_PAUSE_NS);
    }

    @Override
    public void close() {
        try {
            selector.close();
        } catch (IOException ignored) {
            // nothing left to release
        }
    }
}
