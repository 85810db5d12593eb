package org.miron.bt.formats;

import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;

/** The outcome of BtFormatConverter.convert: the model was converted, or nothing changed and here is why. */
public final class Conversion {
    private final List<ConversionProblem> problems;
    private final Map<EObject, EObject> replacements;

    Conversion(List<ConversionProblem> problems, Map<EObject, EObject> replacements) {
        this.problems = List.copyOf(problems);
        this.replacements = Map.copyOf(replacements);
    }

    /**
     * Nodes the conversion replaced by nodes of another class (SubTreePlus by SubTree...), old to
     * new; other nodes were changed in place. For callers that hold nodes of the model.
     */
    public Map<EObject, EObject> getReplacements() {
        return replacements;
    }

    public boolean succeeded() {
        return problems.isEmpty();
    }

    /** The elements that have no equivalent in the target version, in file order; empty on success. */
    public List<ConversionProblem> getProblems() {
        return problems;
    }
}
