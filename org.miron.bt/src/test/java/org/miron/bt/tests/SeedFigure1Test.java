package org.miron.bt.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.validation.Issue;
import org.junit.Test;
import org.miron.bt.bt.Action;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.Sequence;
import org.miron.bt.bt.SubtreePlus;
import org.miron.testkit.RepositoryRoot;

/**
 * The seed's Figure 1, verbatim. It is a fragment: GoTo and PickDeliverCharge are defined
 * elsewhere, so exactly those references are reported; everything else maps onto the metamodel.
 */
public class SeedFigure1Test {
    private final File figure = new File(BtFiles.RESOURCES, "seed/figure1.bt");

    @Test
    public void parsesIntoTheSeedMetamodel() {
        XtextResource resource = BtFiles.load(figure);
        assertTrue(resource.getErrors().stream().noneMatch(e -> e.getMessage().contains("mismatched")));
        BTModel model = BtFiles.model(resource);
        assertEquals("Main", model.getMain_tree_to_execute());
        assertEquals(List.of("Main", "Charge", "Deliver"),
                model.getTrees().stream().map(BehaviorTree::getName).collect(Collectors.toList()));

        SubtreePlus main = (SubtreePlus) model.getTrees().get(0).getNodes().get(0);
        assertEquals("PickDeliverChargeSubtree", main.getName());

        Sequence deliver = (Sequence) model.getTrees().get(2).getNodes().get(0);
        assertEquals("deliver", deliver.getName());
        SubtreePlus goTo = (SubtreePlus) deliver.getNodes().get(0);
        assertEquals(List.of("__shared_blackboard=false", "x_input=-8.08", "y_input=4.11"),
                goTo.getAttributes().stream().map(a -> a.getName() + "=" + a.getValue()).collect(Collectors.toList()));
        Action drop = (Action) deliver.getNodes().get(1);
        assertEquals("objectdrop", drop.attribute("ID"));
        assertEquals("-1", drop.attribute("obj_index"));
        assertEquals("Action", drop.getTag());
        Attribute first = drop.getAttributes().get(0);
        assertEquals("ID", first.getName());
    }

    @Test
    public void reportsOnlyTheTreesTheFragmentLacks() {
        List<Issue> issues = BtFiles.validate(BtFiles.load(figure));
        assertEquals(BtFiles.describe(issues), List.of(
                "5:21 ERROR unknown SubTree ID 'PickDeliverCharge': no BehaviorTree with this ID in this file or the files it includes",
                "10:23 ERROR unknown SubTree ID 'GoTo': no BehaviorTree with this ID in this file or the files it includes",
                "16:23 ERROR unknown SubTree ID 'GoTo': no BehaviorTree with this ID in this file or the files it includes"),
                issues.stream().map(i -> i.getLineNumber() + ":" + i.getColumn() + " " + i.getSeverity() + " " + i.getMessage())
                        .collect(Collectors.toList()));
    }

    @Test
    public void theCompletedExampleResolvesEveryTree() {
        File example = RepositoryRoot.file("examples/intralogistics/intralogistics.bt");
        BTModel model = BtFiles.model(BtFiles.load(example));
        for (String tree : List.of("Main", "Charge", "Deliver", "Pick", "PickDeliverCharge", "DeliverCharge", "GoTo")) {
            assertTrue(tree, model.getTrees().stream().anyMatch(t -> tree.equals(t.getName())));
        }
        SubtreePlus main = (SubtreePlus) model.getTrees().get(0).getNodes().get(0);
        assertEquals("PickDeliverCharge", main.getBehaviorTree().getName());
    }
}
