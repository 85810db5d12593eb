package org.miron.executor;

import static org.junit.Assert.assertEquals;
import static org.miron.executor.NodeStatus.FAILURE;
import static org.miron.executor.NodeStatus.IDLE;
import static org.miron.executor.NodeStatus.RUNNING;
import static org.miron.executor.NodeStatus.SUCCESS;

import org.junit.Before;
import org.junit.Test;
import org.miron.executor.decorators.LoopNode;
import org.miron.executor.decorators.TimeoutNode;

/** Inverter, Force*, Repeat, Retry (both spellings), Timeout and the blackboard checks (decorators.bt). */
public class DecoratorNodesTest {
    private final ActionRegistry registry = new ActionRegistry();
    private final FakeClock clock = new FakeClock();
    private ScriptedAction a;

    @Before
    public void setUp() {
        a = ScriptedAction.register(registry, "A");
    }

    private Tree tree(String id) {
        return Fixtures.build("decorators.bt", id, registry, new TreeContext(clock, 5));
    }

    @Test
    public void inverterSwapsFinishedStatuses() {
        Tree tree = tree("Inv");
        assertEquals(FAILURE, tree.tickRoot());
        a.returns(FAILURE);
        assertEquals(SUCCESS, tree.tickRoot());
        a.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
    }

    @Test
    public void forceSuccessAndForceFailure() {
        Tree ok = tree("ForceOk");
        Tree ko = tree("ForceKo");
        a.returns(FAILURE);
        assertEquals(SUCCESS, ok.tickRoot());
        assertEquals(FAILURE, ko.tickRoot());
        a.returns(SUCCESS);
        assertEquals(SUCCESS, ok.tickRoot());
        assertEquals(FAILURE, ko.tickRoot());
        a.returns(RUNNING);
        assertEquals(RUNNING, ok.tickRoot());
        assertEquals(RUNNING, ko.tickRoot());
    }

    @Test
    public void repeatTicksTheChildAgainWithinOneTick() {
        Tree tree = tree("Repeat3");
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals(3, a.ticks);
        assertEquals(IDLE, tree.find("A").get().status());
    }

    @Test
    public void repeatCountsSuccessesAcrossRunningTicks() {
        Tree tree = tree("Repeat3");
        assertEquals(SUCCESS, tree.tickRoot());
        a.ticks = 0;
        a.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        a.returns(SUCCESS);
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals("1 running tick, then 3 successes", 4, a.ticks);
    }

    @Test
    public void repeatFailsOnFailureAndResetsItsCount() {
        Tree tree = tree("Repeat3");
        a.returns(RUNNING);
        tree.tickRoot();
        a.returns(FAILURE);
        assertEquals(FAILURE, tree.tickRoot());
        a.ticks = 0;
        a.returns(SUCCESS);
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals(3, a.ticks);
    }

    @Test
    public void repeatZeroSucceedsWithoutTickingTheChild() {
        assertEquals(SUCCESS, tree("Repeat0").tickRoot());
        assertEquals(0, a.ticks);
    }

    @Test
    public void repeatForeverYieldsAfterTheLoopBound() {
        Tree tree = tree("RepeatForever");
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals("the context allows 5 child ticks per tick", 5, a.ticks);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(10, a.ticks);
        a.returns(FAILURE);
        assertEquals(FAILURE, tree.tickRoot());
    }

    @Test
    public void repeatForeverOverAlwaysSuccessDoesNotHang() {
        Tree tree = Fixtures.build("decorators.bt", "RepeatForeverOverSuccess", registry, new TreeContext());
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(RUNNING, tree.tickRoot());
    }

    @Test
    public void retryRetriesFailuresWithinOneTick() {
        Tree tree = tree("Retry3");
        a.returns(FAILURE);
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals(3, a.ticks);
        a.returns(SUCCESS);
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals(4, a.ticks);
    }

    @Test
    public void retryCountsFailuresAcrossRunningTicks() {
        Tree tree = tree("Retry3");
        a.returns(FAILURE);
        tree.tickRoot();
        a.ticks = 0;
        a.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        a.returns(FAILURE);
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals("1 running tick, then 3 failed attempts", 4, a.ticks);
    }

    @Test
    public void retryOldSpellingBehavesTheSame() {
        Tree tree = tree("RetryOldSpelling");
        assertEquals(LoopNode.class, tree.root().getClass());
        a.returns(FAILURE);
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals(2, a.ticks);
    }

    @Test
    public void retryForeverYieldsAfterTheLoopBound() {
        Tree tree = tree("RetryForever");
        a.returns(FAILURE);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(5, a.ticks);
        a.returns(SUCCESS);
        assertEquals(SUCCESS, tree.tickRoot());
    }

    @Test
    public void timeoutHaltsTheChildWhenTimeIsUp() {
        Tree tree = tree("Timeout100");
        assertEquals(TimeoutNode.class, tree.root().getClass());
        a.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        clock.advance(99);
        assertEquals(RUNNING, tree.tickRoot());
        clock.advance(1);
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals(1, a.halts);
        assertEquals("the expired tick does not tick the child", 2, a.ticks);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals("the next run restarts the child and the clock", 2, a.starts);
        clock.advance(99);
        assertEquals(RUNNING, tree.tickRoot());
    }

    @Test
    public void timeoutPassesAFinishedChildThroughAndRestartsItsClock() {
        Tree tree = tree("Timeout100");
        a.returns(RUNNING);
        tree.tickRoot();
        clock.advance(90);
        a.returns(SUCCESS);
        assertEquals(SUCCESS, tree.tickRoot());
        a.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        clock.advance(90);
        assertEquals("a new clock started with the new run", RUNNING, tree.tickRoot());
        assertEquals(0, a.halts);
    }

    @Test
    public void timeoutHaltedFromOutsideForgetsItsClock() {
        Tree tree = tree("Timeout100");
        a.returns(RUNNING);
        tree.tickRoot();
        clock.advance(500);
        tree.haltTree();
        assertEquals(1, a.halts);
        assertEquals(RUNNING, tree.tickRoot());
    }

    @Test
    public void blackboardCheckIntTicksTheChildOnlyWhenEqual() {
        Tree tree = tree("CheckInt");
        assertEquals("missing value: mismatch", FAILURE, tree.tickRoot());
        assertEquals(0, a.ticks);
        tree.blackboard().set("count", 3);
        assertEquals(SUCCESS, tree.tickRoot());
        tree.blackboard().set("count", "3");
        assertEquals(SUCCESS, tree.tickRoot());
        tree.blackboard().set("count", 4);
        assertEquals(FAILURE, tree.tickRoot());
        tree.blackboard().set("count", "three");
        assertEquals("not an integer: mismatch", FAILURE, tree.tickRoot());
        assertEquals(2, a.ticks);
    }

    @Test
    public void blackboardCheckHaltsARunningChildOnMismatch() {
        Tree tree = tree("CheckIntOrSuccess");
        tree.blackboard().set("count", 3);
        a.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        tree.blackboard().set("count", 2);
        assertEquals("return_on_mismatch", SUCCESS, tree.tickRoot());
        assertEquals(1, a.halts);
    }

    @Test
    public void blackboardCheckDoubleComparesNumbers() {
        Tree tree = tree("CheckDouble");
        tree.blackboard().set("speed", 0.5);
        assertEquals(SUCCESS, tree.tickRoot());
        tree.blackboard().set("speed", "0.50");
        assertEquals(SUCCESS, tree.tickRoot());
        tree.blackboard().set("speed", 0.51);
        assertEquals(FAILURE, tree.tickRoot());
    }

    @Test
    public void blackboardCheckStringReturnsTheMismatchStatusAsked() {
        Tree tree = tree("CheckString");
        tree.blackboard().set("mode", "slow");
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(0, a.ticks);
        tree.blackboard().set("mode", "fast");
        a.returns(FAILURE);
        assertEquals(FAILURE, tree.tickRoot());
    }
}
