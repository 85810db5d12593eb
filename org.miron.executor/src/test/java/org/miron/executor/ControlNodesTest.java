package org.miron.executor;

import static org.junit.Assert.assertEquals;
import static org.miron.executor.NodeStatus.FAILURE;
import static org.miron.executor.NodeStatus.IDLE;
import static org.miron.executor.NodeStatus.RUNNING;
import static org.miron.executor.NodeStatus.SUCCESS;

import org.junit.Before;
import org.junit.Test;

/** Sequence, Fallback, their Reactive and Star variants, tick by tick (controls.bt). */
public class ControlNodesTest {
    private final ActionRegistry registry = new ActionRegistry();
    private ScriptedAction a;
    private ScriptedAction b;
    private ScriptedAction c;
    private final NodeStatus[] cond = {SUCCESS};

    @Before
    public void setUp() {
        a = ScriptedAction.register(registry, "A");
        b = ScriptedAction.register(registry, "B");
        c = ScriptedAction.register(registry, "C");
        registry.registerCondition("Cond", ports -> cond[0]);
    }

    private Tree tree(String id) {
        return Fixtures.build("controls.bt", id, registry, new TreeContext());
    }

    @Test
    public void sequenceSucceedsWhenAllChildrenSucceedAndResetsThem() {
        Tree tree = tree("Seq");
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals(1, a.ticks);
        assertEquals(1, b.ticks);
        assertEquals(1, c.ticks);
        for (Node node : tree.nodes()) {
            assertEquals(node.path(), IDLE, node.status());
        }
    }

    @Test
    public void sequenceResumesAtTheRunningChild() {
        Tree tree = tree("Seq");
        b.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals("A is not ticked again while B runs", 1, a.ticks);
        assertEquals(2, b.ticks);
        assertEquals(0, c.ticks);
        b.returns(SUCCESS);
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals(1, a.ticks);
        assertEquals(1, c.ticks);
    }

    @Test
    public void sequenceFailureHaltsAndStartsOver() {
        Tree tree = tree("Seq");
        b.returns(FAILURE);
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals(0, c.ticks);
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals("a new run starts from the first child", 2, a.ticks);
    }

    @Test
    public void haltingARunningSequenceHaltsTheRunningChildAndResets() {
        Tree tree = tree("Seq");
        b.returns(RUNNING);
        tree.tickRoot();
        tree.haltTree();
        assertEquals(1, b.halts);
        assertEquals(0, a.halts);
        assertEquals(IDLE, tree.root().status());
        b.returns(SUCCESS);
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals(2, a.ticks);
    }

    @Test
    public void reactiveSequenceRechecksEarlierChildrenEveryTick() {
        Tree tree = tree("ReactiveSeq");
        a.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(2, a.ticks);
        assertEquals("A was started once and kept running", 1, a.starts);
        cond[0] = FAILURE;
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals("the failing condition halts the running action", 1, a.halts);
        assertEquals(0, b.ticks);
    }

    @Test
    public void reactiveSequenceHaltsChildrenAfterARunningOne() {
        Tree tree = tree("ReactiveSeq");
        b.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        a.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals("B runs after A, which now runs again: B is halted", 1, b.halts);
        assertEquals(IDLE, tree.find("B").get().status());
    }

    @Test
    public void sequenceStarRetriesTheFailedChildWithoutRestarting() {
        Tree tree = tree("SeqStar");
        b.returns(FAILURE);
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals("A is not ticked again after B failed", 1, a.ticks);
        assertEquals(2, b.ticks);
        b.returns(SUCCESS);
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals(1, a.ticks);
        assertEquals(1, c.ticks);
        assertEquals("after SUCCESS it starts over", SUCCESS, tree.tickRoot());
        assertEquals(2, a.ticks);
    }

    @Test
    public void haltingARunningSequenceStarResetsItsPosition() {
        Tree tree = tree("SeqStar");
        b.returns(RUNNING);
        tree.tickRoot();
        tree.haltTree();
        assertEquals(1, b.halts);
        b.returns(SUCCESS);
        tree.tickRoot();
        assertEquals(2, a.ticks);
    }

    @Test
    public void sequenceStarKeepsItsPositionWhenItsParentRetries() {
        Tree tree = tree("RetrySeqStar");
        b.returns(FAILURE);
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals("retried 3 times from B, A succeeded once", 1, a.ticks);
        assertEquals(3, b.ticks);
    }

    @Test
    public void fallbackStopsAtTheFirstSuccessAndResumesAtTheRunningChild() {
        Tree tree = tree("Fb");
        a.returns(FAILURE);
        b.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(1, a.ticks);
        b.returns(SUCCESS);
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals(0, c.ticks);
        assertEquals(3, b.ticks);
    }

    @Test
    public void fallbackFailsWhenAllFailAndStartsOver() {
        Tree tree = tree("Fb");
        a.returns(FAILURE);
        b.returns(FAILURE);
        c.returns(FAILURE);
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals(2, a.ticks);
        assertEquals(2, c.ticks);
    }

    @Test
    public void reactiveFallbackPreemptsARunningChild() {
        Tree tree = tree("ReactiveFb");
        cond[0] = FAILURE;
        a.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(1, a.starts);
        cond[0] = SUCCESS;
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals(1, a.halts);
    }

    @Test
    public void fallbackStarKeepsItsPositionAfterSuccess() {
        Tree tree = tree("FbStar");
        a.returns(FAILURE);
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals("A failed once and is not ticked again", 1, a.ticks);
        assertEquals(2, b.ticks);
        b.returns(FAILURE);
        c.returns(FAILURE);
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals(1, a.ticks);
        assertEquals("after FAILURE it starts over", FAILURE, tree.tickRoot());
        assertEquals(2, a.ticks);
    }
}
