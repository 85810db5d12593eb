package org.miron.dds.transport;

/** A DDS entity could not be created (unknown type, native library not loadable, bad QoS). */
public final class DdsException extends Exception {
    private static final long serialVersionUID = 1L;

    public DdsException(String message) {
        super(message);
    }

    public DdsException(String message, Throwable cause) {
        super(message, cause);
    }
}
