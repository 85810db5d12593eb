package org.miron.runtime.bus;

/**
 * A component's connection to the bus, whatever carries it: ZeroMQ sockets to a broker elsewhere
 * ({@link BusClient}) or a link to a broker in the same process (the broker's
 * {@code LocalBus}). Components program against this, and {@link BusLink} says which one they get.
 */
public interface Bus extends AutoCloseable {
    /** Receives one bus message: topic and body (the second frame, empty if absent). */
    interface Handler {
        void onMessage(String topic, byte[] body);
    }

    /**
     * A handler that neither blocks nor takes long (it decodes or queues): a link to a broker in
     * the same process may run it on the broker's own thread instead of waking a thread for it,
     * one hand-over less on the way in. Anything it publishes leaves after the message it handles.
     */
    interface QuickHandler extends Handler {
    }

    /** Told once the broker's replay of an epoch is complete; {@code first}: the first epoch seen. */
    interface SyncListener {
        void synced(String epoch, boolean first);
    }

    /** Follows the broker's epochs and replay of the last-value cache; before {@link #start}. */
    Bus onBrokerSync(SyncListener listener);

    Bus start();

    /**
     * Sends a message to the bus; never waits for a peer (a socket client queues it and drops the
     * oldest when the queue is full; a local link has handed it to the broker when this returns).
     */
    void publish(String topic, String body);

    /**
     * Publishes and remembers the message as the current value of {@code key}, for a connection
     * that outlives a broker restart to re-announce.
     */
    void publishRetained(String key, String topic, String body);

    /** Waits until the broker takes our output. */
    boolean awaitReady(long timeoutMs) throws InterruptedException;

    /** Waits until every queued message has left. */
    boolean flush(long timeoutMs) throws InterruptedException;

    @Override
    void close();
}
