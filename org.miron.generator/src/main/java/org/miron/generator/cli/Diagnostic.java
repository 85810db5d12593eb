package org.miron.generator.cli;

/** One problem in a model file, printed the way compilers do: file:line:col: severity: message. */
public record Diagnostic(String file, int line, int column, Severity severity, String message)
        implements Comparable<Diagnostic> {

    public enum Severity {
        ERROR, WARNING;

        @Override
        public String toString() {
            return name().toLowerCase();
        }
    }

    /** Keeps one diagnostic per line: parser messages may quote text that spans lines. */
    public Diagnostic {
        message = message == null ? "" : message.replaceAll("\\s*\\R\\s*", " ");
    }

    @Override
    public String toString() {
        return line > 0 ? file + ":" + line + ":" + column + ": " + severity + ": " + message
                : file + ": " + severity + ": " + message;
    }

    @Override
    public int compareTo(Diagnostic other) {
        int byFile = file.compareTo(other.file);
        if (byFile != 0) {
            return byFile;
        }
        if (line != other.line) {
            return Integer.compare(line, other.line);
        }
        return column != other.column ? Integer.compare(column, other.column) : message.compareTo(other.message);
    }
}
