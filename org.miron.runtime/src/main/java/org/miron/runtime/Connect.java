package org.miron.runtime;

import org.zeromq.ZMQ;

/**
 * Connects a socket with a short ZMTP handshake timeout. JeroMQ 0.6.0 sometimes completes the TCP
 * connect but never starts the handshake on the connecting side (a race in its I/O poller, see
 * zeromq/jeromq PR #1022, a few percent of fresh connections); the connection then idles until the
 * handshake timer (30 s by default) drops it and reconnects. With a short timer the stalled
 * attempt is retried within about a second. Every connecting socket in MIRoN goes through here.
 */
public final class Connect {
    public static final int HANDSHAKE_MS = 1000;

    private Connect() {
    }

    public static ZMQ.Socket connect(ZMQ.Socket socket, String endpoint) {
        socket.setHandshakeIvl(HANDSHAKE_MS);
        socket.connect(endpoint);
        return socket;
    }
}
