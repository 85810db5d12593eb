package org.miron.executor.scripting;

/** A script failed while running (as BT.CPP's RuntimeError from a script); the node adds where. */
public class ScriptException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public ScriptException(String message) {
        super(message);
    }
}
