package org.miron.generator;

import java.util.List;

/**
 * Thrown by {@link MironGenerator#doGenerate} when a model cannot be generated; nothing was
 * written. Callers that want to report the errors themselves use {@link MironGenerator#stage}.
 */
public class GenerationException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    private final List<GenerationError> errors;

    public GenerationException(List<GenerationError> errors) {
        super(errors.size() + " generation error(s), first: " + errors.get(0).message());
        this.errors = List.copyOf(errors);
    }

    public List<GenerationError> errors() {
        return errors;
    }
}
