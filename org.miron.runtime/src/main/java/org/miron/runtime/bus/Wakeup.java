package org.miron.runtime.bus;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.channels.Pipe;
import java.nio.channels.SelectableChannel;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * Wakes a socket loop blocked in a ZeroMQ poll from any thread: a java.nio pipe whose read end is
 * registered in the poller (ZeroMQ sockets themselves are single-threaded, so another thread
 * cannot signal over an inproc socket without one per thread). Signals coalesce: one byte is in
 * flight at most, so a burst of publishes costs one wake-up.
 */
final class Wakeup implements AutoCloseable {
    private final Pipe pipe;
    private final AtomicBoolean pending = new AtomicBoolean();
    private final ByteBuffer one = ByteBuffer.allocate(1);
    private final ByteBuffer sink = ByteBuffer.allocate(64);

    Wakeup() {
        try {
            pipe = Pipe.open();
            pipe.source().configureBlocking(false);
            pipe.sink().configureBlocking(false);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot open the bus wake-up pipe", e);
        }
    }

    /** What the poller watches for POLLIN. */
    SelectableChannel channel() {
        return pipe.source();
    }

    /** Any thread: makes the next (or current) poll return. */
    void signal() {
        if (pending.compareAndSet(false, true)) {
            synchronized (one) {
                one.clear();
                try {
                    pipe.sink().write(one); // non-blocking; a full pipe already holds a wake-up
                } catch (IOException e) {
                    pending.set(false); // closed: the loop is ending
                }
            }
        }
    }

    /**
     * Loop thread, before it looks at its queue: consumes the signal; true if there was one. A
     * signal raised after this call wakes the next poll, so nothing queued afterwards waits for a
     * timeout. The pipe is emptied before {@code pending} is reset, not after: a signal that
     * slipped in between would otherwise have its byte read here while leaving {@code pending}
     * set, and every later {@link #signal} would skip the write until the poll timed out.
     */
    boolean clear() {
        boolean signalled = false;
        try {
            sink.clear();
            while (pipe.source().read(sink) > 0) {
                signalled = true;
                sink.clear();
            }
        } catch (IOException ignored) {
            // closed: the loop is ending
        }
        pending.set(false);
        return signalled;
    }

    @Override
    public void close() {
        try {
            pipe.sink().close();
            pipe.source().close();
        } catch (IOException ignored) {
            // nothing left to release
        }
    }
}
