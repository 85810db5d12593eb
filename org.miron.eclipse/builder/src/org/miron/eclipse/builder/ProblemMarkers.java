package org.miron.eclipse.builder;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.Collection;
import java.util.Map;

import org.eclipse.core.resources.IFile;
import org.eclipse.core.resources.IMarker;
import org.eclipse.core.resources.IResource;
import org.eclipse.core.runtime.CoreException;
import org.miron.generator.standalone.Diagnostic;

/**
 * The builder's problem markers ({@code org.miron.eclipse.problem}, a persistent problem marker):
 * one per diagnostic, with its line, character range, severity, message and issue code
 * (attribute {@code code}, docs/issue-codes.md).
 */
final class ProblemMarkers {
    static final String TYPE = "org.miron.eclipse.problem";
    /** The marker attribute holding the diagnostic's issue code. */
    static final String CODE = "code";

    private ProblemMarkers() {
    }

    /** Replaces the file's markers with these diagnostics. */
    static void replace(IFile file, Collection<Diagnostic> diagnostics) throws CoreException {
        if (!file.exists()) {
            return;
        }
        file.deleteMarkers(TYPE, false, IResource.DEPTH_ZERO);
        if (diagnostics.isEmpty()) {
            return;
        }
        String text = text(file);
        for (Diagnostic d : diagnostics) {
            int line = Math.max(d.line(), 1);
            int start = offset(text, line, Math.max(d.column(), 1));
            int end = d.endLine() > 0 ? offset(text, d.endLine(), Math.max(d.endColumn(), 1)) : lineEnd(text, start);
            Map<String, Object> attributes = Map.of(
                    IMarker.LINE_NUMBER, line,
                    IMarker.CHAR_START, start,
                    IMarker.CHAR_END, Math.max(end, Math.min(start + 1, text.length())),
                    IMarker.SEVERITY, d.severity() == Diagnostic.Severity.ERROR ? IMarker.SEVERITY_ERROR
                            : IMarker.SEVERITY_WARNING,
                    IMarker.MESSAGE, d.message(),
                    CODE, d.code() == null ? "" : d.code());
            file.createMarker(TYPE, attributes);
        }
    }

    /** One more error on a file, on its first line (a generator's failure, not a check's). */
    static void add(IFile file, String message) throws CoreException {
        file.createMarker(TYPE, Map.of(IMarker.LINE_NUMBER, 1, IMarker.SEVERITY, IMarker.SEVERITY_ERROR,
                IMarker.MESSAGE, message, CODE, ""));
    }

    private static String text(IFile file) {
        try {
            return Files.readString(ModelFiles.toFile(file).toPath(), StandardCharsets.UTF_8);
        } catch (IOException | RuntimeException unreadable) {
            return "";
        }
    }

    /** The character offset of a 1-based line and column, clamped to the text. */
    static int offset(String text, int line, int column) {
        int offset = 0;
        for (int l = 1; l < line && offset < text.length(); l++) {
            int newline = text.indexOf('\n', offset);
            if (newline < 0) {
                return text.length();
            }
            offset = newline + 1;
        }
        return Math.min(offset + column - 1, text.length());
    }

    private static int lineEnd(String text, int offset) {
        int newline = text.indexOf('\n', offset);
        return newline < 0 ? text.length() : newline;
    }
}
