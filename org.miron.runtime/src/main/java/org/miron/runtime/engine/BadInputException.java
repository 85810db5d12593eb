package org.miron.runtime.engine;

/** A bus message the engine cannot use; it is counted, logged and dropped. */
public final class BadInputException extends Exception {
    /** malformed: not parseable; unknown: no such topic/input/varpoint; type: wrong value type or range. */
    public enum Kind { MALFORMED, UNKNOWN, TYPE }

    private final Kind kind;

    public BadInputException(Kind kind, String message) {
        super(message);
        this.kind = kind;
    }

    public Kind kind() {
        return kind;
    }
}
