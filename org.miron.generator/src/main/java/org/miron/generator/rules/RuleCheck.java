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
 * The rule and requirement checks as the MIRoN validator's {@link RuleAnalysis} (registered in
 * META-INF/services): analyses the model once as the generators do, runs {@link RuleConflicts} with
 * a one-second budget and {@link RequirementCheck}. A model the generators would refuse is not
 * analysed (its errors are reported by the validator or by `miron generate`).
 */
public final class RuleCheck implements RuleAnalysis {
    /** Time budget of one model's check (docs/issue-codes.md, miron.rule-check-cut). */
    public static final long BUDGET_MS = 1000;
    /** Past this many rules the model is not analysed at all (its analysis alone would take seconds). */
    public static final int MAX_RULES = 500;

    @Override
    public List<Finding> analyse(MironModel model) {
        List<org.miron.dsl.miron.Rule> own = model.getSentences().stream()
                .filter(org.miron.dsl.miron.Rule.class::isInstance).map(org.miron.dsl.miron.Rule.class::cast).toList();
        boolean requirements = model.getSentences().stream().anyMatch(Requirement.class::isInstance);
        boolean cut = own.size() > MAX_RULES;
        List<Finding> findings = new ArrayList<>();
        if (cut) {
            findings.add(new Finding(own.get(0), "miron.rule-check-cut", "rule check skipped: " + own.size()
                    + " rules, more than " + MAX_RULES + "; conflicts between them are not ruled out"));
            if (!requirements) {
                return findings; // the analysis alone would take seconds, and nothing else needs it
            }
        }
        List<GenerationError> errors = new ArrayList<>();
        AdaptationModel m;
        try {
            m = new ModelAnalyser(errors).analyse(model, "check", WeightPolicy.NEED);
        } catch (RuntimeException e) { // an unresolved or half-typed model: other checks report it
            return findings;
        }
        if (!errors.isEmpty()) {
            return findings;
        }
        if (!cut && !m.rules.isEmpty()) {
            for (RuleConflicts.Finding f : new RuleConflicts(m, BUDGET_MS).analyse()) {
                findings.add(new Finding(f.rule(), f.code(), f.message()));
            }
        }
        findings.addAll(RequirementCheck.findings(m));
        return findings;
    }
}
