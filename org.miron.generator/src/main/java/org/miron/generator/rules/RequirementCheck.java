package org.miron.generator.rules;

import java.util.ArrayList;
import java.util.List;
import org.miron.dsl.validation.RuleAnalysis.Finding;
import org.miron.generator.AdaptationModel;

/**
 * Requirements no run can violate or no run can meet given the declared domains: asks
 * {@link RequirementDomains} about each requirement's formula tree, the one name.requirements.json
 * holds. Run by {@link RuleCheck} on the model it has analysed, so a check analyses it once.
 */
final class RequirementCheck {
    private RequirementCheck() {
    }

    static List<Finding> findings(AdaptationModel m) {
        if (m.requirements.isEmpty()) {
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
