package org.miron.runtime.bus;

import java.util.List;

/**
 * Where a component's bus connection goes: {@link #sockets} to a broker in another process (or
 * reached as if it were), or a broker's {@code local()} link when both are in one process, which
 * hands messages over without sockets.
 */
@FunctionalInterface
public interface BusLink {
    /** A connection, not started, subscribed to the topic prefixes. */
    Bus open(String name, List<String> subscriptions, Bus.Handler handler);

    /** ZeroMQ sockets to the broker's XSUB ({@code busIn}) and XPUB ({@code busOut}, may be null). */
    static BusLink sockets(String busIn, String busOut) {
        return (name, subscriptions, handler) -> new BusClient(name, busIn, busOut, subscriptions, handler);
    }
}
