package org.miron.bt.script;

/**
 * A syntax error in a script: offset and length in the script text (0-based, in characters of the
 * decoded attribute value), and a message.
 */
public final class ScriptSyntaxError {
    private final int offset;
    private final int length;
    private final String message;

    public ScriptSyntaxError(int offset, int length, String message) {
        this.offset = offset;
        this.length = length;
        this.message = message;
    }

    public int getOffset() {
        return offset;
    }

    public int getLength() {
        return length;
    }

    public String getMessage() {
        return message;
    }

    @Override
    public String toString() {
        return offset + ": " + message;
    }
}
