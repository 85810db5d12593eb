package org.miron.generator;

import java.util.List;

/** The outcome of generating one model: its files, not yet written, and what went wrong. */
public record StagedGeneration(StagedFiles files, List<GenerationError> errors) {

    public boolean succeeded() {
        return errors.isEmpty();
    }
}
