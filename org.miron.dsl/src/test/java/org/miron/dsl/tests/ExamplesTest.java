package org.miron.dsl.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.junit.Test;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.SubtreePlus;
import org.miron.dsl.miron.ArchBinding;
import org.miron.dsl.miron.BehaviorTreeEnumType;
import org.miron.dsl.miron.BehaviorTreeLiteral;
import org.miron.dsl.miron.BtBinding;
import org.miron.dsl.miron.ImpactIntensity;
import org.miron.dsl.miron.InsertionType;
import org.miron.dsl.miron.MironModel;
import org.miron.dsl.miron.NumericSampledType;
import org.miron.dsl.miron.Rule;
import org.miron.dsl.miron.VariationPoint;
import org.miron.dsl.roqme.BinaryExpression;
import org.miron.dsl.roqme.EnumValue;
import org.miron.dsl.roqme.RoqmeModel;

/** The shipped examples, starting with the seed's Figure 3 (examples/intralogistics). */
public class ExamplesTest {

    private static Resource check(String path) {
        Resource resource = Models.load(new File(Models.root(), path));
        List<Issue> errors = Models.validateAll(resource).stream().filter(i -> i.getSeverity() == Severity.ERROR)
                .collect(Collectors.toList());
        assertEquals(errors.stream().map(Models::format).collect(Collectors.joining("\n")), 0, errors.size());
        assertEquals(List.of(), Models.unresolved(resource));
        return resource;
    }

    @Test
    public void intralogisticsRoqme() {
        RoqmeModel model = (RoqmeModel) check("examples/intralogistics/intralogistics.roqme").getContents().get(0);
        assertEquals("Intralogistics", model.getNamespace());
        assertTrue(model.getSentences().size() >= 5);
    }

    @Test
    public void figure3() {
        MironModel model = (MironModel) check("examples/intralogistics/intralogistics.miron").getContents().get(0);
        assertEquals(2, model.getImports().size());
        VariationPoint task = (VariationPoint) model.getVariables().get(0);
        BehaviorTreeEnumType type = (BehaviorTreeEnumType) task.getDeclaration();
        assertEquals(4, type.getLiterals().size());
        BehaviorTreeLiteral dock = (BehaviorTreeLiteral) type.getLiterals().get(2);
        assertEquals("Charge", ((BehaviorTree) dock.getReference()).getName());
        assertTrue(((BehaviorTreeLiteral) type.getLiterals().get(3)).isPreset());
        BtBinding binding = (BtBinding) task.getBinding();
        assertEquals(InsertionType.IN, binding.getInsertionType());
        assertTrue(binding.getTargets().get(0) instanceof SubtreePlus);
        assertEquals("PickDeliverChargeSubtree", binding.getTargets().get(0).getName());

        VariationPoint maxVelocity = (VariationPoint) model.getVariables().get(1);
        NumericSampledType sampled = (NumericSampledType) maxVelocity.getDeclaration();
        assertEquals(10.0, sampled.getLower(), 0);
        assertEquals(1.0, sampled.getPrecision(), 0);
        assertEquals(100.0, sampled.getUpper(), 0);
        assertEquals(2, sampled.getSamples().size());
        assertEquals(ImpactIntensity.POSITIVE, sampled.getSamples().get(0).getImpacts().get(0).getIntensity());
        assertEquals("safety", sampled.getSamples().get(0).getImpacts().get(0).getProperty().getName());
        ArchBinding arch = (ArchBinding) maxVelocity.getBinding();
        assertEquals("CommNavigationObjects", arch.getParameterSetRepository());
        assertEquals("CdParameter", arch.getParameterSet());
        assertEquals("SmartCdServer", arch.getComponent());
        assertEquals("transvel", arch.getParameter());

        Rule rule = (Rule) model.getSentences().get(2); // imports first: Import is a Sentence (seed)
        assertEquals("noBattery", rule.getName());
        BinaryExpression consequence = (BinaryExpression) rule.getImplies().get(0).getTerm();
        assertEquals("dock", ((EnumValue) consequence.getRight()).getLiteral().getName());
    }

    @Test
    public void nav2() {
        check("examples/nav2/nav2.roqme");
        MironModel model = (MironModel) check("examples/nav2/nav2.miron").getContents().get(0);
        assertNotNull(model);
    }

    @Test
    public void hospitalDelivery() {
        check("examples/hospital-delivery/hospital.roqme");
        MironModel model = (MironModel) check("examples/hospital-delivery/hospital.miron").getContents().get(0);
        assertEquals("HospitalDelivery", model.getNamespace());
        assertEquals(7, model.getVariables().size());
        assertEquals(2 + 6 + 3, model.getSentences().size()); // imports, rules, requirements
        VariationPoint inflation = (VariationPoint) model.getVariables().get(4);
        BtBinding binding = (BtBinding) inflation.getBinding();
        org.miron.dsl.bt.BtXPath.Result selected = org.miron.dsl.bt.BtXPath.evaluate(binding.getXpath(),
                binding.getTargets().get(0));
        assertEquals(2, selected.selections.size());
        assertTrue(selected.selections.stream().allMatch(org.miron.dsl.bt.BtXPath.Selection::isAttribute));
        Rule crowded = (Rule) model.getSentences().get(2);
        assertEquals(3, crowded.getImplies().size());
    }
}
