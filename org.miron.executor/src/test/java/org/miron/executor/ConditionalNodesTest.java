package org.miron.executor;

import static org.junit.Assert.assertEquals;
import static org.miron.executor.NodeStatus.FAILURE;
import static org.miron.executor.NodeStatus.IDLE;
import static org.miron.executor.NodeStatus.RUNNING;
import static org.miron.executor.NodeStatus.SUCCESS;

import org.junit.Before;
import org.junit.Test;
import org.miron.executor.controls.IfThenElseNode;
import org.miron.executor.controls.WhileDoElseNode;

/** IfThenElse and WhileDoElse (builtins.bt), tick by tick; C is the condition, A then, B else. */
public class ConditionalNodesTest {
    private final ActionRegistry registry = new ActionRegistry();
    private ScriptedAction c;
    private ScriptedAction a;
    private ScriptedAction b;

    @Before
    public void setUp() {
        c = ScriptedAction.register(registry, "C");
        a = ScriptedAction.register(registry, "A");
        b = ScriptedAction.register(registry, "B");
    }

    private Tree tree(String id) {
        return Fixtures.build("builtins.bt", id, registry, new TreeContext(new FakeClock()));
    }

    @Test
    public void ifThenElseRunsThenOnSuccessAndElseOnFailure() {
        Tree tree = tree("If3");
        assertEquals(IfThenElseNode.class, tree.root().getClass());
        a.returns(SUCCESS);
        b.returns(FAILURE);
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals(1, a.ticks);
        assertEquals(0, b.ticks);
        c.returns(FAILURE);
        assertEquals("the else-branch's status", FAILURE, tree.tickRoot());
        assertEquals(1, a.ticks);
        assertEquals(1, b.ticks);
        assertEquals(IDLE, tree.find("C").get().status());
    }

    @Test
    public void ifThenElsePassesARunningCondition() {
        Tree tree = tree("If3");
        c.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(0, a.ticks + b.ticks);
        c.returns(SUCCESS);
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals(1, a.ticks);
    }

    @Test
    public void ifThenElseDoesNotRecheckTheConditionWhileABranchRuns() {
        Tree tree = tree("If3");
        a.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        c.returns(FAILURE);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals("not reactive", 1, c.ticks);
        assertEquals(2, a.ticks);
        a.returns(SUCCESS);
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals("B's status", SUCCESS, tree.tickRoot());
        assertEquals("a new run asks the condition again, now FAILURE: B", 2, c.ticks);
        assertEquals(1, b.ticks);
    }

    @Test
    public void ifThenWithoutElseFailsWhenTheConditionFails() {
        Tree tree = tree("If2");
        c.returns(FAILURE);
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals(0, a.ticks);
        c.returns(SUCCESS);
        a.returns(FAILURE);
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals(1, a.ticks);
    }

    @Test
    public void haltingAnIfThenElseHaltsTheBranchAndForgetsTheChoice() {
        Tree tree = tree("If3");
        a.returns(RUNNING);
        tree.tickRoot();
        tree.haltTree();
        assertEquals(1, a.halts);
        assertEquals(0, ((IfThenElseNode) tree.root()).currentBranch());
        c.returns(FAILURE);
        b.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals("the condition decides again", 2, c.ticks);
        assertEquals(1, b.ticks);
    }

    @Test
    public void whileDoElseRechecksTheConditionOnEveryTick() {
        Tree tree = tree("While3");
        assertEquals(WhileDoElseNode.class, tree.root().getClass());
        a.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(2, c.ticks);
        assertEquals(2, a.ticks);
        a.returns(SUCCESS);
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals(0, a.halts);
    }

    @Test
    public void whileDoElseHaltsTheBranchTheConditionLeaves() {
        Tree tree = tree("While3");
        a.returns(RUNNING);
        b.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        c.returns(FAILURE);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals("then-branch halted before the else-branch runs", 1, a.halts);
        assertEquals(1, b.ticks);
        c.returns(SUCCESS);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(1, b.halts);
        assertEquals("A starts again", 2, a.starts);
        b.returns(FAILURE);
        c.returns(FAILURE);
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals(2, a.halts);
    }

    @Test
    public void whileDoElseLeavesTheRunningBranchAloneWhileTheConditionRuns() {
        Tree tree = tree("While3");
        a.returns(RUNNING);
        tree.tickRoot();
        c.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(0, a.halts);
        assertEquals(1, a.ticks);
    }

    @Test
    public void whileDoWithoutElseFailsAndHaltsTheBranchWhenTheConditionFails() {
        Tree tree = tree("While2");
        a.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        c.returns(FAILURE);
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals(1, a.halts);
        assertEquals(IDLE, tree.find("A").get().status());
    }

    @Test
    public void haltingAWhileDoElseHaltsItsRunningBranch() {
        Tree tree = tree("While3");
        a.returns(RUNNING);
        tree.tickRoot();
        tree.haltTree();
        assertEquals(1, a.halts);
        assertEquals(IDLE, tree.root().status());
    }
}
