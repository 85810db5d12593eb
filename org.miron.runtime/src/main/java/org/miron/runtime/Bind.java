package org.miron.runtime;

import org.zeromq.ZMQ;
import org.zeromq.ZMQException;

/**
 * Binds a socket and, when it cannot, says which endpoint and why in words: JeroMQ's own message
 * is the bare error number ("Errno 48"). Every binding socket in MIRoN goes through here.
 */
public final class Bind {
    private Bind() {
    }

    /** @throws IllegalStateException naming the endpoint and the reason */
    public static ZMQ.Socket bind(ZMQ.Socket socket, String endpoint) {
        try {
            socket.bind(endpoint);
            return socket;
        } catch (ZMQException e) {
            throw new IllegalStateException(endpoint + ": " + reason(e), e);
        } catch (IllegalArgumentException e) { // JeroMQ's answer to an endpoint it cannot parse
            throw new IllegalStateException(endpoint + ": not an endpoint (" + e.getMessage() + ")", e);
        }
    }

    private static String reason(ZMQException e) {
        int code = e.getErrorCode();
        if (code == ZMQ.Error.EADDRINUSE.getCode()) {
            return "address already in use (is another MIRoN component running there?)";
        }
        if (code == ZMQ.Error.EADDRNOTAVAIL.getCode()) {
            return "address not available on this machine";
        }
        if (code == ZMQ.Error.EACCESS.getCode()) {
            return "permission denied (a port below 1024?)";
        }
        try {
            return ZMQ.Error.findByCode(code).getMessage();
        } catch (IllegalArgumentException unknownCode) {
            return e.getMessage();
        }
    }
}
