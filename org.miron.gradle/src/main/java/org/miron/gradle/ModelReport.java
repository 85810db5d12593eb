package org.miron.gradle;

import java.util.List;

import org.gradle.api.GradleException;
import org.gradle.api.logging.Logger;
import org.miron.generator.standalone.Diagnostic;

/**
 * Tells the user about model problems the way `miron check` does, one
 * {@code file:line:col: error [code]: message} line each, and fails the task with a short message:
 * a model error is the user's to fix, so Gradle shows no stack trace for it.
 */
final class ModelReport {
    private ModelReport() {
    }

    static void log(Logger logger, List<Diagnostic> diagnostics) {
        for (Diagnostic d : diagnostics) {
            if (d.severity() == Diagnostic.Severity.ERROR) {
                logger.error(d.toString());
            } else {
                logger.warn(d.toString());
            }
        }
    }

    static GradleException failure(List<Diagnostic> diagnostics) {
        long errors = diagnostics.stream().filter(d -> d.severity() == Diagnostic.Severity.ERROR).count();
        return new GradleException(errors + (errors == 1 ? " error" : " errors")
                + " in the MIRoN models (listed above as file:line:col: error [code]: message)");
    }
}
