package org.miron.executor;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;
import static org.miron.executor.NodeStatus.FAILURE;
import static org.miron.executor.NodeStatus.IDLE;
import static org.miron.executor.NodeStatus.RUNNING;
import static org.miron.executor.NodeStatus.SUCCESS;

import org.junit.Before;
import org.junit.Test;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.BtFactory;
import org.miron.bt.bt.Parallel;

/** Parallel thresholds, positive, negative and from the blackboard (controls.bt). */
public class ParallelNodeTest {
    private final ActionRegistry registry = new ActionRegistry();
    private ScriptedAction a;
    private ScriptedAction b;
    private ScriptedAction c;

    @Before
    public void setUp() {
        a = ScriptedAction.register(registry, "A");
        b = ScriptedAction.register(registry, "B");
        c = ScriptedAction.register(registry, "C");
    }

    private Tree tree(String id) {
        return Fixtures.build("controls.bt", id, registry, new TreeContext());
    }

    @Test
    public void succeedsAtTheThresholdRemembersFinishedChildrenAndHaltsTheRest() {
        Tree tree = tree("Par2of3");
        b.returns(RUNNING);
        c.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals("A finished and is not ticked again", 1, a.ticks);
        assertEquals(2, b.ticks);
        b.returns(SUCCESS);
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals("C still ran and is halted", 1, c.halts);
        for (Node node : tree.nodes()) {
            assertEquals(node.path(), IDLE, node.status());
        }
    }

    @Test
    public void failsAtTheFailureThreshold() {
        Tree tree = tree("Par2of3");
        a.returns(FAILURE);
        b.returns(RUNNING);
        c.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        b.returns(FAILURE);
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals(1, c.halts);
    }

    @Test
    public void minusOneMeansAllChildrenAndOneFailureIsEnoughByDefault() {
        Tree tree = tree("ParAll");
        b.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        b.returns(SUCCESS);
        assertEquals(SUCCESS, tree.tickRoot());

        a.returns(FAILURE);
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals("failure_threshold defaults to 1: stops at the first failure", 2, b.ticks);
    }

    @Test
    public void failsAsSoonAsSuccessCannotBeReached() {
        // success_threshold -2 = 2 of 3, failure_threshold -1 = 3: two failures already make 2 successes impossible
        Tree tree = tree("ParNegative");
        a.returns(FAILURE);
        b.returns(FAILURE);
        c.returns(RUNNING);
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals(0, c.ticks);
    }

    @Test
    public void readsThresholdsFromTheBlackboardAtTickTime() {
        Tree tree = tree("ParFromBlackboard");
        a.returns(RUNNING);
        try {
            tree.tickRoot();
            fail("success_threshold points at an unset entry");
        } catch (BtRuntimeException expected) {
            assertTrue(expected.getMessage(), expected.getMessage().contains("need"));
        }
        tree.blackboard().set("need", 1);
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals("B succeeded, the running A is halted", 1, a.halts);

        tree.blackboard().set("need", "3");
        try {
            tree.tickRoot();
            fail("3 of 2 children can never succeed");
        } catch (BtRuntimeException expected) {
            assertTrue(expected.getMessage(), expected.getMessage().contains("success_threshold=3"));
        }
    }

    @Test
    public void aLiteralThresholdLargerThanTheChildrenIsABuildError() {
        BtFactory f = BtFactory.eINSTANCE;
        BehaviorTree tree = f.createBehaviorTree();
        tree.setName("T");
        Parallel parallel = f.createParallel();
        parallel.setTag("Parallel");
        Attribute threshold = f.createAttribute();
        threshold.setName("success_threshold");
        threshold.setValue("-3");
        parallel.getAttributes().add(threshold);
        var child = f.createAlwaysSuccess();
        child.setTag("AlwaysSuccess");
        parallel.getNodes().add(child);
        parallel.getNodes().add(org.eclipse.emf.ecore.util.EcoreUtil.copy(child));
        tree.getNodes().add(parallel);
        try {
            new TreeBuilder(registry, new TreeContext()).build(tree);
            fail("-3 with 2 children");
        } catch (BtBuildException expected) {
            assertTrue(expected.getMessage(), expected.getMessage().contains("success_threshold=-3"));
        }
        threshold.setValue("-2");
        assertEquals(SUCCESS, new TreeBuilder(registry, new TreeContext()).build(tree).tickRoot());
    }
}
