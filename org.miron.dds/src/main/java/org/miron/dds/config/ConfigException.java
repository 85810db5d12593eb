package org.miron.dds.config;

/** A refused bridge configuration: where (line, column, JSON pointer) and why. */
public final class ConfigException extends Exception {
    private static final long serialVersionUID = 1L;
    private final int line;
    private final int column;
    private final String pointer;
    private final String reason;

    public ConfigException(int line, int column, String pointer, String reason) {
        super(reason);
        this.line = line;
        this.column = column;
        this.pointer = pointer;
        this.reason = reason;
    }

    public int line() {
        return line;
    }

    public int column() {
        return column;
    }

    /** The JSON pointer of the offending value ("" for the document). */
    public String pointer() {
        return pointer;
    }

    /** {@code FILE:LINE:COL: error [dds-config]: POINTER: REASON}, as the model commands report. */
    public String format(String file) {
        return file + ":" + line + ":" + column + ": error [dds-config]: " + (pointer.isEmpty() ? "" : pointer + ": ") + reason;
    }
}
