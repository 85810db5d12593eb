package org.miron.generator;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.eclipse.emf.ecore.resource.Resource;
import org.junit.Test;
import org.miron.dsl.miron.MironModel;
import org.miron.generator.rules.RuleConflicts;
import org.miron.generator.standalone.ModelLoader;

/**
 * The rule check on the examples: their rules do not conflict, and every situation is tried (the
 * number of situations is printed with the time it took; the 1 s budget is far away).
 */
public class RuleCheckExamplesTest {

    private static RuleConflicts analysed(String example, String model, List<RuleConflicts.Finding> into) {
        return analysed(example, model, into, 60_000); // a generous budget: a slow machine still tries all
    }

    private static RuleConflicts analysed(String example, String model, List<RuleConflicts.Finding> into, long budgetMs) {
        Resource resource = new ModelLoader().load(Toolchain.ROOT.resolve("examples/" + example + "/" + model + ".miron").toFile());
        List<GenerationError> errors = new ArrayList<>();
        AdaptationModel m = new ModelAnalyser(errors).analyse((MironModel) resource.getContents().get(0), model,
                WeightPolicy.NEED);
        assertEquals(errors.toString(), 0, errors.size());
        RuleConflicts check = new RuleConflicts(m, budgetMs);
        long start = System.nanoTime();
        into.addAll(check.analyse());
        System.out.printf("rule check of %s: %d situations in %.1f ms%n", model, check.situations(),
                (System.nanoTime() - start) / 1e6);
        return check;
    }

    @Test
    public void theExamplesRulesHoldTogetherInEverySituation() {
        for (String[] example : new String[][] {{"intralogistics", "intralogistics"}, {"hospital-delivery", "hospital"}}) {
            List<RuleConflicts.Finding> findings = new ArrayList<>();
            RuleConflicts check = analysed(example[0], example[1], findings);
            assertEquals(example[1] + ": " + findings, List.of(), findings.stream().map(RuleConflicts.Finding::message).toList());
            assertEquals("every situation tried", check.situations(), check.tried());
            assertTrue(check.situations() > 1);
        }
    }

    /** Without time nothing is tried, and the check says so instead of reporting a clean model. */
    @Test
    public void aCutSearchIsReported() {
        List<RuleConflicts.Finding> findings = new ArrayList<>();
        RuleConflicts check = analysed("hospital-delivery", "hospital", findings, 0);
        assertEquals(0, check.tried());
        assertEquals(findings.toString(), 1, findings.size());
        assertEquals("miron.rule-check-cut", findings.get(0).code());
        assertTrue(findings.get(0).message(), findings.get(0).message().startsWith("rule check stopped after 0 ms: 0 of "
                + check.situations() + " situations tried without a conflict"));
    }
}
