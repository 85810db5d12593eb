package org.miron.dsl.validation;

import java.util.List;
import org.eclipse.emf.ecore.EObject;
import org.miron.dsl.miron.MironModel;

/**
 * A check of how a model's rules interact (conflicts, rules that never apply or are always
 * overridden), which needs the generators' view of the model: implemented in org.miron.generator
 * and found with {@link java.util.ServiceLoader}, so `miron check` and the language server report
 * it, while the language alone (its tests, a bare Eclipse editor) runs without it.
 */
public interface RuleAnalysis {

    /** A warning on an element (a rule) of the analysed model. */
    record Finding(EObject element, String code, String message) {
    }

    /** Findings on the rules of {@code model}; empty when it cannot be analysed (errors elsewhere). */
    List<Finding> analyse(MironModel model);
}
