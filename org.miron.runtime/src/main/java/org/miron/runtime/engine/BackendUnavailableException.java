package org.miron.runtime.engine;

/** The solver backend cannot run at all (e.g. no minizinc binary): a start-up error. */
public final class BackendUnavailableException extends Exception {
    public BackendUnavailableException(String message) {
        super(message);
    }
}
