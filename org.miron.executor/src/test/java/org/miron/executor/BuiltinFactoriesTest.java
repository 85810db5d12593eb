package org.miron.executor;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;

import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.junit.Test;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.BtFactory;
import org.miron.bt.bt.BtPackage;
import org.miron.bt.bt.ControlNode;
import org.miron.bt.bt.DecoratorNode;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.nodes.NodeCatalogue;
import org.miron.bt.nodes.NodeKind;
import org.miron.bt.nodes.NodeModel;
import org.miron.executor.controls.OrderedNode;
import org.miron.executor.controls.OrderedNodeV4;
import org.miron.executor.decorators.LoopNodeV4;

/**
 * The executor's per-version factory tables against the catalogue of built-in nodes, and the
 * load-time checks read from the catalogue, on trees built in code (the validator would refuse
 * these files before the executor saw them).
 */
public class BuiltinFactoriesTest {
    private static final BtFactory F = BtFactory.eINSTANCE;

    /** Fails when a node is added to the catalogue without its executor class, or the other way round. */
    @Test
    public void eachVersionsTableHasExactlyTheCataloguesBuiltins() {
        for (int version : new int[] { NodeCatalogue.V3, NodeCatalogue.V4 }) {
            Set<String> catalogue = NodeCatalogue.in(version).stream()
                    .filter(n -> !n.explicitForm() && n.kind() != NodeKind.SUBTREE).map(NodeModel::tag)
                    .collect(Collectors.toCollection(TreeSet::new));
            assertEquals("version " + version, catalogue, new TreeSet<>(BuiltinFactories.table(version).keySet()));
        }
    }

    @Test
    public void aRenamedCounterpartIsBuiltAsTheVersionsNode() {
        // SequenceStar in a version-4 tree runs as SequenceWithMemory (as the executor always did), and back.
        assertEquals(OrderedNodeV4.class, build(4, control("SequenceStar")).root().getClass());
        assertEquals(OrderedNode.class, build(3, control("SequenceWithMemory")).root().getClass());
        TreeNode retry = decorator(BtPackage.Literals.RETRY_UNTIL_SUCCESS, "RetryUntilSuccesful", "num_attempts", "2");
        assertEquals(LoopNodeV4.class, build(4, retry).root().getClass());
    }

    @Test
    public void aBuiltinOfTheOtherVersionIsANodeTheApplicationRegistered() {
        // BT.CPP 3 looks any element name up among the registered nodes: ParallelAll is one there.
        ControlNode parallelAll = control("ParallelAll");
        try {
            build(3, parallelAll);
            fail("ParallelAll is not a version-3 built-in");
        } catch (BtBuildException expected) {
            assertTrue(expected.getMessage(), expected.getMessage().contains("no control node or decorator is "
                    + "registered for ID 'ParallelAll'"));
        }
    }

    @Test
    public void requiredPortsAndLiteralTypesComeFromTheCatalogue() {
        assertBuildError(3, decorator(BtPackage.Literals.TIMEOUT, "Timeout"), "T/Timeout: missing parameter msec");
        assertBuildError(4, decorator(BtPackage.Literals.TIMEOUT, "Timeout", "msec", "-5"),
                "T/Timeout: msec: not a non-negative integer: '-5'");
        assertBuildError(3, decorator(BtPackage.Literals.REPEAT, "Repeat", "num_cycles", "-2"),
                "T/Repeat: num_cycles: not an integer of at least -1: '-2'");
        assertBuildError(4, decorator(BtPackage.Literals.RUN_ONCE, "RunOnce", "then_skip", "maybe"),
                "T/RunOnce: then_skip: not a boolean");
        // a blackboard pointer is no literal: checked when read
        build(4, decorator(BtPackage.Literals.REPEAT, "Repeat", "num_cycles", "{n}"));
        // Switch2 needs its variable and both cases in both versions
        ControlNode switch2 = control("Switch2");
        switch2.getNodes().add(leaf());
        assertBuildError(4, switch2, "T/Switch2: missing parameter variable");
    }

    @Test
    public void childCountsComeFromTheCatalogue() {
        DecoratorNode inverter = decorator(BtPackage.Literals.INVERTER, "Inverter");
        inverter.getSurplus().add(leaf());
        assertBuildError(4, inverter, "a decorator has exactly one child, Inverter has 2");
        assertBuildError(3, control("Switch2"), "T/Switch2: Switch2 takes exactly 3 children, has 2");
        ControlNode empty = control("Sequence");
        empty.getNodes().clear();
        assertBuildError(3, empty, "T/Sequence: Sequence needs at least one child");
    }

    private static void assertBuildError(int version, TreeNode root, String message) {
        try {
            build(version, root);
            fail("expected: " + message);
        } catch (BtBuildException expected) {
            assertTrue(expected.getMessage(), expected.getMessage().contains(message));
        }
    }

    private static Tree build(int version, TreeNode root) {
        BTModel model = F.createBTModel();
        model.getAttributes().add(attribute("BTCPP_format", String.valueOf(version)));
        BehaviorTree tree = F.createBehaviorTree();
        tree.setName("T");
        tree.getNodes().add(root);
        model.getTrees().add(tree);
        return new TreeBuilder(new ActionRegistry(), new TreeContext()).build(tree);
    }

    private static ControlNode control(String tag) {
        ControlNode control = (ControlNode) F.create(BtPackage.Literals.SEQUENCE);
        control.setTag(tag);
        control.getNodes().add(leaf());
        control.getNodes().add(leaf());
        return control;
    }

    private static DecoratorNode decorator(EClass type, String tag, String... attributes) {
        DecoratorNode decorator = (DecoratorNode) F.create(type);
        decorator.setTag(tag);
        for (int i = 0; i < attributes.length; i += 2) {
            decorator.getAttributes().add(attribute(attributes[i], attributes[i + 1]));
        }
        decorator.setNode(leaf());
        return decorator;
    }

    private static TreeNode leaf() {
        TreeNode leaf = F.createAlwaysSuccess();
        leaf.setTag("AlwaysSuccess");
        return EcoreUtil.copy(leaf);
    }

    private static Attribute attribute(String name, String value) {
        Attribute attribute = F.createAttribute();
        attribute.setName(name);
        attribute.setValue(value);
        return attribute;
    }
}
