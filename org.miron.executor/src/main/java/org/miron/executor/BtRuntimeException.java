package org.miron.executor;

/** A tree that cannot run as written: a missing or malformed port, a child returning IDLE... */
public class BtRuntimeException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public BtRuntimeException(String message) {
        super(message);
    }

    public BtRuntimeException(String message, Throwable cause) {
        super(message, cause);
    }
}
