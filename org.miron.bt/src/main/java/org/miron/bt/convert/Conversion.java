package org.miron.bt.convert;

import java.util.List;

/** The outcome of BtFormatConverter.convert: the model was converted, or nothing changed and here is why. */
public final class Conversion {
    private final List<ConversionProblem> problems;

    Conversion(List<ConversionProblem> problems) {
        this.problems = List.copyOf(problems);
    }

    public boolean succeeded() {
        return problems.isEmpty();
    }

    /** The elements that have no equivalent in the target version, in file order; empty on success. */
    public List<ConversionProblem> getProblems() {
        return problems;
    }
}
