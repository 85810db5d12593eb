package org.miron.executor;

import static org.junit.Assert.assertEquals;
import static org.miron.executor.NodeStatus.FAILURE;
import static org.miron.executor.NodeStatus.RUNNING;
import static org.miron.executor.NodeStatus.SUCCESS;

import org.junit.Before;
import org.junit.Test;

/** Switch: case selection, default child, halting the branch it leaves (switch.bt). */
public class SwitchNodeTest {
    private final ActionRegistry registry = new ActionRegistry();
    private ScriptedAction a;
    private ScriptedAction b;
    private ScriptedAction c;
    private ScriptedAction d;

    @Before
    public void setUp() {
        a = ScriptedAction.register(registry, "A");
        b = ScriptedAction.register(registry, "B");
        c = ScriptedAction.register(registry, "C");
        d = ScriptedAction.register(registry, "D");
    }

    private Tree tree(String id) {
        return Fixtures.build("switch.bt", id, registry, new TreeContext());
    }

    @Test
    public void aMissingVariableSelectsTheDefault() {
        Tree tree = tree("Switch");
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals(1, d.ticks);
        assertEquals(0, a.ticks + b.ticks + c.ticks);
    }

    @Test
    public void selectsTheMatchingCaseAndTheDefaultOtherwise() {
        Tree tree = tree("Switch");
        tree.blackboard().set("sel", "b");
        b.returns(FAILURE);
        assertEquals(FAILURE, tree.tickRoot());
        tree.blackboard().set("sel", "c");
        assertEquals(SUCCESS, tree.tickRoot());
        tree.blackboard().set("sel", "zzz");
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals(1, b.ticks);
        assertEquals(1, c.ticks);
        assertEquals(1, d.ticks);
    }

    @Test
    public void haltsTheRunningBranchWhenTheChoiceChanges() {
        Tree tree = tree("Switch");
        tree.blackboard().set("sel", "a");
        a.returns(RUNNING);
        b.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(0, a.halts);
        tree.blackboard().set("sel", "b");
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(1, a.halts);
        assertEquals(1, b.starts);
        tree.blackboard().set("sel", null);
        d.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(1, b.halts);
        assertEquals(1, d.starts);
    }

    @Test
    public void keepsTheSameBranchRunningWhileTheChoiceStays() {
        Tree tree = tree("Switch");
        tree.blackboard().set("sel", "c");
        c.returns(RUNNING);
        tree.tickRoot();
        tree.tickRoot();
        tree.tickRoot();
        assertEquals(1, c.starts);
        assertEquals(3, c.ticks);
        assertEquals(0, c.halts);
    }

    @Test
    public void haltsARunningSubtreeBranchAndReadsCasesFromTheBlackboard() {
        Tree tree = tree("SwitchCaseFromBlackboard");
        tree.blackboard().set("wanted", "work");
        tree.blackboard().set("sel", "work");
        c.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(1, a.ticks);
        tree.blackboard().set("sel", "other");
        assertEquals("the default AlwaysFailure", FAILURE, tree.tickRoot());
        assertEquals("C, deep in the Work subtree, is halted", 1, c.halts);
        assertEquals(NodeStatus.IDLE, tree.find("work").get().status());
    }
}
