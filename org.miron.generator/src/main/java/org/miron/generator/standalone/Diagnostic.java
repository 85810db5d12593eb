package org.miron.generator.standalone;

import java.util.List;

/**
 * One problem in a model file, printed the way compilers do: {@code file:line:col: severity [code]: message}.
 * Lines and columns are 1-based, 0 when unknown; the end position (endLine:endColumn, the column just
 * after the problem's text) is 0 when unknown. The code is the language's stable issue code (see
 * docs/issue-codes.md), null for most problems found by a generator; data is what a quick fix needs.
 */
public record Diagnostic(String file, int line, int column, int endLine, int endColumn, Severity severity,
        String code, List<String> data, String message) implements Comparable<Diagnostic> {

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
        data = data == null ? List.of() : List.copyOf(data);
    }

    /** A problem without issue code, data or end position (e.g. found by a generator). */
    public Diagnostic(String file, int line, int column, Severity severity, String message) {
        this(file, line, column, 0, 0, severity, null, List.of(), message);
    }

    @Override
    public String toString() {
        String kind = code == null ? severity.toString() : severity + " [" + code + "]";
        return line > 0 ? file + ":" + line + ":" + column + ": " + kind + ": " + message
                : file + ": " + kind + ": " + message;
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
        if (column != other.column) {
            return Integer.compare(column, other.column);
        }
        int byMessage = message.compareTo(other.message);
        return byMessage != 0 ? byMessage : String.valueOf(code).compareTo(String.valueOf(other.code));
    }
}
