package org.miron.dds.types;

/** A message definition that cannot be used: where (file, line, column of the offending token) and why. */
public final class DefinitionException extends Exception {
    private static final long serialVersionUID = 1L;
    private final String file;
    private final int line;
    private final int column;

    public DefinitionException(String file, int line, int column, String reason) {
        super(reason);
        this.file = file;
        this.line = line;
        this.column = column;
    }

    public String file() {
        return file;
    }

    public int line() {
        return line;
    }

    public int column() {
        return column;
    }

    /** {@code FILE:LINE:COL: error [dds-types]: REASON}, as the other start-up errors. */
    public String format() {
        return file + ":" + line + ":" + column + ": error [dds-types]: " + getMessage();
    }
}
