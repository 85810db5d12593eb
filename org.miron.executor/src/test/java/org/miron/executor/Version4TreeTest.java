package org.miron.executor;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;
import static org.miron.executor.NodeStatus.FAILURE;
import static org.miron.executor.NodeStatus.RUNNING;
import static org.miron.executor.NodeStatus.SUCCESS;

import java.util.Optional;

import org.junit.Test;
import org.miron.executor.actions.AlwaysSuccessNode;
import org.miron.executor.controls.OrderedNode;
import org.miron.executor.controls.OrderedNodeV4;

/**
 * Version-4 behaviour the oracle tests cannot show: enums registered in the registry, time
 * (Sleep with a fake clock), the loop guard, the v3/v4 split by BTCPP_format, bad scripts.
 */
public class Version4TreeTest {
    private enum Light { RED, GREEN }

    private final ActionRegistry registry = new ActionRegistry();
    private final ScriptedAction drive = ScriptedAction.register(registry, "Drive");
    private final ScriptedAction lift = ScriptedAction.register(registry, "Lift");
    private final FakeClock clock = new FakeClock();

    private Tree build(String id) {
        return Fixtures.build("v4-nodes.xml", id, registry, new TreeContext(clock, 50));
    }

    @Test
    public void scriptsReadEnumsRegisteredInTheRegistry() {
        registry.registerScriptingEnums(Light.class);
        Tree tree = build("Enums");
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals(Optional.of(1.0), tree.blackboard().get("light"));
        assertEquals(1, drive.starts);
    }

    @Test
    public void withoutTheEnumTheNameIsAnUnknownKeyAtTickTime() {
        Tree tree = build("Enums");
        try {
            tree.tickRoot();
            fail();
        } catch (BtRuntimeException expected) {
            assertTrue(expected.getMessage(), expected.getMessage().contains("Enums/Sequence/Script: code: Variable not found: GREEN"));
        }
    }

    @Test
    public void sleepRunsUntilItsTimeHasPassed() {
        Tree tree = build("Sleeping");
        assertEquals(RUNNING, tree.tickRoot());
        clock.advance(99);
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(0, drive.starts);
        clock.advance(1);
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals(1, drive.starts);
    }

    @Test
    public void aTimeoutOfZeroNeverExpiresInVersion4() {
        Tree tree = build("NoTimeout");
        drive.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        clock.advance(10_000);
        assertEquals(RUNNING, tree.tickRoot());
        drive.returns(SUCCESS);
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals(0, drive.halts);
    }

    @Test
    public void sequenceWithMemoryKeepsItsPlaceWhenHaltedAsBtCpp48() {
        Tree tree = build("Memory");
        lift.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
        tree.haltTree();
        assertEquals(1, lift.halts);
        lift.returns(SUCCESS);
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals("Drive is not run again after the halt", 1, drive.starts);
    }

    @Test
    public void repeatForeverOverAnInstantSuccessYieldsInsteadOfHanging() {
        Tree tree = build("Forever");
        assertEquals(RUNNING, tree.tickRoot());
        assertEquals(RUNNING, tree.tickExactlyOnce());
    }

    @Test
    public void autoremapSharesEveryKeyButTheOnesStartingWithUnderscore() {
        Tree tree = build("Private");
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals(Optional.of(2L), tree.blackboard().get("speed"));
        assertEquals(Optional.of(1L), tree.blackboard().get("_secret"));
        assertEquals("new keys are created in the parent too", Optional.of("here"), tree.blackboard().get("made"));
    }

    @Test
    public void theFileVersionDecidesTheSemantics() {
        Tree v4 = build("Memory");
        assertTrue(v4.root() instanceof OrderedNodeV4);
        registry.setFallback(spec -> new AlwaysSuccessNode(spec.info()));
        Tree v3 = Fixtures.build("controls.bt", "SeqStar", registry, new TreeContext(clock));
        assertFalse(v3.nodes().stream().anyMatch(n -> n instanceof OrderedNodeV4));
        assertTrue(v3.nodes().stream().anyMatch(n -> n instanceof OrderedNode));
    }

    @Test
    public void aScriptThatDoesNotParseIsRefusedWithItsPositionWhenLoading() {
        try {
            new TreeBuilder(registry, new TreeContext()).build(Fixtures.resource("v4-bad-script.xml"));
            fail();
        } catch (BtBuildException expected) {
            assertTrue(expected.getMessage(), expected.getMessage().matches("(?s).*v4-bad-script\\.xml:4:\\d+: .*"));
        }
    }

    @Test
    public void aFailedConditionOnTheRootReturnsFailureWithoutTickingIt() {
        Tree tree = build("Sleeping");
        tree.root().useConditions(new Conditions(java.util.Map.of(Conditions.Kind.FAILURE_IF, scope -> 1.0), java.util.Map.of()));
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals(NodeStatus.IDLE, tree.find("Sleep").orElseThrow().status());
    }
}
