package org.miron.generator.rules;

import java.util.ArrayList;
import java.util.List;
import org.miron.dsl.miron.MironModel;
import org.miron.dsl.miron.Requirement;
import org.miron.dsl.validation.RuleAnalysis;
import org.miron.generator.AdaptationModel;
import org.miron.generator.GenerationError;
import org.miron.generator.ModelAnalyser;
import org.miron.generator.WeightPolicy;

/**
 * Requirements no run can violate or no run can meet given the declared domains, as the MIRoN
 * validator's {@link RuleAnalysis} (registered in META-INF/services beside {@link RuleCheck}):
 * analyses the model as the generators do and asks {@link RequirementDomains} about each
 * requirement's formula tree, the one name.requirements.json holds.
 */
public final class RequirementCheck implements RuleAnalysis {

    @Override
    public List<Finding> analyse(MironModel model) {
        if (model.getSentences().stream().noneMatch(Requirement.class::isInstance)) {
            return List.of();
        }
        List<GenerationError> errors = new ArrayList<>();
        AdaptationModel m;
        try {
            m = new ModelAnalyser(errors).analyse(model, "check", WeightPolicy.NEED);
        } catch (RuntimeException e) { // an unresolved or half-typed model: other checks report it
            return List.of();
        }
        if (!errors.isEmpty()) {
            return List.of();
        }
        RequirementDomains domains = new RequirementDomains(m);
        List<Finding> findings = new ArrayList<>();
        for (AdaptationModel.TranslatedRequirement r : m.requirements) {
            RequirementDomains.Outcomes o = domains.outcomes(r);
            String name = r.requirement().getName();
            if (!o.canBeFalse()) {
                findings.add(new Finding(r.requirement(), "miron.requirement-trivial", "requirement " + name
                        + " can never be violated: given the declared ranges and values, no run breaks it"));
            } else if (!o.canBeTrue()) {
                findings.add(new Finding(r.requirement(), "miron.requirement-unsatisfiable", "requirement " + name
                        + " can never be met: given the declared ranges and values, no run satisfies it"));
            }
        }
        return findings;
    }
}
