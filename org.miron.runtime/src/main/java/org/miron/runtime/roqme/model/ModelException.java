package org.miron.runtime.roqme.model;

/**
 * A runtime model the provider cannot run. The message is one line,
 * {@code file:line:col: error [code]: message}, naming the declaration's {@code at} when known.
 */
public final class ModelException extends Exception {
    private static final long serialVersionUID = 1L;

    public ModelException(String at, String code, String message) {
        super(at + ": error [" + code + "]: " + message);
    }
}
