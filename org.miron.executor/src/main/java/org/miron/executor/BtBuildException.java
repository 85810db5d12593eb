package org.miron.executor;

/** A model that cannot be turned into a runnable tree (unknown action, bad structure, load errors). */
public class BtBuildException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public BtBuildException(String message) {
        super(message);
    }

    public BtBuildException(String message, Throwable cause) {
        super(message, cause);
    }
}
