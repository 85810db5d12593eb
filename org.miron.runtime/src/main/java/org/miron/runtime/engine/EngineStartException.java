package org.miron.runtime.engine;

/** The engine cannot start; the message is meant for the operator, not a stack trace. */
public final class EngineStartException extends Exception {
    public EngineStartException(String message) {
        super(message);
    }
}
