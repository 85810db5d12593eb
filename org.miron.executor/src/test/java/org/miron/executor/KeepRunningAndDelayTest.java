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
import org.miron.executor.decorators.DelayNode;
import org.miron.executor.decorators.KeepRunningUntilFailureNode;

/** KeepRunningUntilFailure and Delay (builtins.bt), tick by tick with a hand-moved clock. */
public class KeepRunningAndDelayTest {
    private final ActionRegistry registry = new ActionRegistry();
    private final FakeClock clock = new FakeClock();
    private ScriptedAction a;

    @Before
    public void setUp() {
        a = ScriptedAction.register(registry, "A");
    }

    private Tree tree(String id) {
        return Fixtures.build("builtins.bt", id, registry, new TreeContext(clock));
    }

    @Test
    public void keepRunningTurnsSuccessIntoRunningAndRestartsTheChild() {
        Tree tree = tree("Keep");
        assertEquals(KeepRunningUntilFailureNode.class, tree.root().getClass());
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(IDLE, tree.find("A").get().status());
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals("a new run of the child each tick", 2, a.starts);
        a.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        a.returns(FAILURE);
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals(IDLE, tree.find("A").get().status());
    }

    @Test
    public void haltingKeepRunningHaltsTheChild() {
        Tree tree = tree("Keep");
        a.returns(RUNNING);
        tree.tickRoot();
        tree.haltTree();
        assertEquals(1, a.halts);
    }

    @Test
    public void delayWaitsFromItsFirstTickThenReturnsTheChildsStatus() {
        Tree tree = tree("Delay100");
        assertEquals(DelayNode.class, tree.root().getClass());
        assertEquals(RUNNING, tree.tickRoot());
        clock.advance(99);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals("the child waits", 0, a.ticks);
        clock.advance(1);
        a.returns(FAILURE);
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals(1, a.ticks);
        assertEquals("a new run waits again", RUNNING, tree.tickRoot());
        assertEquals(1, a.ticks);
    }

    @Test
    public void delayKeepsTickingARunningChildWithoutANewDelay() {
        Tree tree = tree("Delay100");
        tree.tickRoot();
        clock.advance(100);
        a.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(2, a.ticks);
        a.returns(SUCCESS);
        assertEquals(SUCCESS, tree.tickRoot());
    }

    @Test
    public void haltingADelayHaltsTheChildAndRestartsTheClock() {
        Tree tree = tree("Delay100");
        tree.tickRoot();
        clock.advance(100);
        a.returns(RUNNING);
        tree.tickRoot();
        tree.haltTree();
        assertEquals(1, a.halts);
        clock.advance(60);
        assertEquals(RUNNING, tree.tickRoot());
        clock.advance(99);
        assertEquals("the new delay counts from the tick after the halt", RUNNING, tree.tickRoot());
        assertEquals(1, a.ticks);
        clock.advance(1);
        tree.tickRoot();
        assertEquals(2, a.ticks);
    }

    @Test
    public void delayZeroTicksTheChildAtOnce() {
        Tree tree = tree("Delay0");
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals(1, a.ticks);
    }

    @Test
    public void delayReadsItsDurationFromTheBlackboard() {
        Tree tree = tree("DelayFromBlackboard");
        tree.blackboard().set("pause", 10);
        assertEquals(RUNNING, tree.tickRoot());
        clock.advance(10);
        assertEquals(SUCCESS, tree.tickRoot());
    }

    @Test
    public void delayWithoutADurationFailsAtTickTime() {
        Tree tree = tree("DelayFromBlackboard");
        try {
            tree.tickRoot();
            fail("no pause on the blackboard");
        } catch (BtRuntimeException e) {
            assertTrue(e.getMessage(), e.getMessage().contains("pause") || e.getMessage().contains("delay_msec"));
        }
    }
}
