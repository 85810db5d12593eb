package org.miron.bt.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertSame;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.util.List;
import java.util.stream.Collectors;

import org.junit.Test;
import org.miron.bt.bt.Action;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.BtPackage;
import org.miron.bt.bt.ControlNode;
import org.miron.bt.bt.CustomControl;
import org.miron.bt.bt.CustomDecorator;
import org.miron.bt.bt.DecoratorNode;
import org.miron.bt.bt.Delay;
import org.miron.bt.bt.Fallback;
import org.miron.bt.bt.RetryUntilSuccess;
import org.miron.bt.bt.Sequence;
import org.miron.bt.bt.Subtree;
import org.miron.bt.bt.SubtreePlus;
import org.miron.bt.bt.Switch;
import org.miron.bt.bt.TreeNode;

/** Each XML element maps to the seed's metamodel class, keeping its written name and attributes. */
public class MetamodelMappingTest {

    private static BTModel model(String file) {
        return BtFiles.model(BtFiles.load(new File(BtFiles.RESOURCES, "valid/" + file)));
    }

    private static TreeNode root(BTModel model, int tree) {
        return model.getTrees().get(tree).getNodes().get(0);
    }

    @Test
    public void reactiveVariantsMapToTheirBaseClassAndKeepTheirTag() {
        ControlNode sequence = (ControlNode) root(model("sequence_family.bt"), 0);
        assertSame(BtPackage.Literals.SEQUENCE_STAR, sequence.getNodes().get(0).eClass());
        assertTrue(sequence.getNodes().get(1) instanceof Sequence);
        assertEquals("ReactiveSequence", sequence.getNodes().get(1).getTag());
        ControlNode fallback = (ControlNode) root(model("fallback_family.bt"), 0);
        assertTrue(fallback.getNodes().get(0) instanceof Fallback);
        assertEquals("ReactiveFallback", fallback.getNodes().get(0).getTag());
    }

    @Test
    public void switchesKeepTheirArity() {
        BTModel model = model("switch_3_4_5.bt");
        for (int i = 0; i < 3; i++) {
            Switch node = (Switch) root(model, i);
            assertEquals("Switch" + (i + 3), node.getTag());
            assertEquals(i + 4, node.getNodes().size());
        }
    }

    @Test
    public void bothRetrySpellingsAreOneClass() {
        Sequence sequence = (Sequence) root(model("retry_both_spellings.bt"), 0);
        List<String> tags = sequence.getNodes().stream().map(n -> {
            assertTrue(n instanceof RetryUntilSuccess);
            assertTrue(((DecoratorNode) n).getNode() instanceof Action);
            return n.getTag();
        }).collect(Collectors.toList());
        assertEquals(List.of("RetryUntilSuccessful", "RetryUntilSuccesful"), tags);
    }

    @Test
    public void compactActionsKeepTheirIdAsTag() {
        Sequence sequence = (Sequence) root(model("compact_actions.bt"), 0);
        Action goTo = (Action) sequence.getNodes().get(0);
        assertEquals("GoTo", goTo.getTag());
        assertEquals("-2.5", goTo.attribute("y"));
        assertNull(goTo.attribute("ID"));
    }

    @Test
    public void builtInsOfBehaviorTreeCpp3MapToTheirClasses() {
        Sequence ifs = (Sequence) root(model("if_then_else.bt"), 0);
        assertSame(BtPackage.Literals.IF_THEN_ELSE, ifs.getNodes().get(0).eClass());
        assertEquals(3, ((ControlNode) ifs.getNodes().get(0)).getNodes().size());
        Sequence whiles = (Sequence) root(model("while_do_else.bt"), 0);
        assertSame(BtPackage.Literals.WHILE_DO_ELSE, whiles.getNodes().get(1).eClass());
        assertSame(BtPackage.Literals.KEEP_RUNNING_UNTIL_FAILURE, root(model("keep_running_until_failure.bt"), 0).eClass());
        Delay delay = (Delay) ((Sequence) root(model("delay.bt"), 0)).getNodes().get(0);
        assertEquals("1500", delay.attribute("delay_msec"));
        assertTrue(delay.getNode() instanceof Action);
    }

    @Test
    public void customNodesWithChildrenKeepTheirRegisteredId() {
        CustomControl scheduler = (CustomControl) root(model("custom_explicit_forms.bt"), 0);
        assertEquals("Control", scheduler.getTag());
        assertEquals("PriorityScheduler", scheduler.getNodeId());
        CustomDecorator rate = (CustomDecorator) scheduler.getNodes().get(0);
        assertEquals("RateController", rate.getNodeId());
        assertEquals(List.of("ID", "hz"), rate.getAttributes().stream().map(a -> a.getName()).collect(Collectors.toList()));

        CustomControl compact = (CustomControl) root(model("compact_with_children.bt"), 0);
        assertEquals("PriorityScheduler", compact.getNodeId());
        CustomControl compactRate = (CustomControl) compact.getNodes().get(0);
        assertEquals("RateController", compactRate.getTag());
        assertEquals(1, compactRate.getNodes().size());
        Action beep = (Action) compact.getNodes().get(2);
        assertEquals("written <Beep></Beep>: still an action", "Beep", beep.getTag());
    }

    @Test
    public void subtreeReferencesResolveAcrossTransitiveIncludes() {
        BTModel model = model("include_transitive.bt");
        SubtreePlus localize = (SubtreePlus) root(model, 0);
        BehaviorTree target = localize.getBehaviorTree();
        assertEquals("Localize", target.getName());
        assertTrue(target.eResource().getURI().lastSegment().equals("localization.bt"));
    }

    @Test
    public void idNeedNotComeFirst() {
        BTModel model = model("subtree_id_not_first.bt");
        assertEquals("Main", model.getTrees().get(0).getName());
        assertEquals("main tree", model.getTrees().get(0).getAttributes().get(0).getValue());
        SubtreePlus go = (SubtreePlus) root(model, 0);
        assertEquals("Go", go.getBehaviorTree().getName());
        assertEquals(List.of("name", "x"), go.getAttributes().stream().map(a -> a.getName()).collect(Collectors.toList()));
        Subtree plain = (Subtree) ((Sequence) root(model("subtree_forms.bt"), 0)).getNodes().get(0);
        assertEquals("Plain", plain.getBehaviorTree().getName());
    }

    @Test
    public void entitiesAndQuotesAreDecoded() {
        Sequence sequence = (Sequence) root(model("entities_and_quotes.bt"), 0);
        assertEquals("single \"quoted\"", sequence.getName());
        Action say = (Action) sequence.getNodes().get(0);
        assertEquals("a < b && c > d", say.attribute("text"));
        assertEquals("\"x\" 'y'", say.attribute("other"));
        assertEquals("AB", say.attribute("code"));
    }

    @Test
    public void rootAttributesKeepTheirOrderAndGiveTheMainTree() {
        BTModel model = model("root_extra_attributes.bt");
        assertEquals("B", model.getMain_tree_to_execute());
        assertEquals(List.of("BTCPP_format", "main_tree_to_execute"),
                model.getAttributes().stream().map(a -> a.getName()).collect(Collectors.toList()));
    }

    @Test
    public void treeNodesModelIsKeptVerbatim() {
        BTModel model = model("tree_nodes_model_verbatim.bt");
        String content = model.getNodesmodel().getContent();
        assertTrue(content, content.startsWith("<TreeNodesModel>"));
        assertTrue(content, content.endsWith("</TreeNodesModel>"));
        assertTrue(content, content.contains("<!-- node declarations are opaque: <this is=\"not parsed\"> -->"));
        assertTrue(content, content.contains("robot's max"));
    }
}
