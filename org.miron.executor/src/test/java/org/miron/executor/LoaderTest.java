package org.miron.executor;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import org.junit.Test;
import org.miron.executor.actions.AlwaysSuccessNode;

/** Loading through the BT language: errors with positions, includes, recursion, tree choice. */
public class LoaderTest {
    private final ActionRegistry registry = new ActionRegistry();

    @Test
    public void anUnknownSubtreeIsReportedWithFileAndLine() {
        try {
            Fixtures.load("errors-unknown-subtree.bt");
            fail();
        } catch (BtBuildException expected) {
            assertTrue(expected.getMessage(), expected.getMessage().contains("errors-unknown-subtree.bt:5:"));
            assertTrue(expected.getMessage(), expected.getMessage().contains("NoSuchTree"));
        }
    }

    @Test
    public void aMissingFileIsReported() {
        try {
            new BtLoader().load(java.nio.file.Path.of("no/such/file.bt"));
            fail();
        } catch (BtBuildException expected) {
            assertTrue(expected.getMessage(), expected.getMessage().contains("file.bt"));
        }
    }

    @Test
    public void treesOfIncludedFilesAreUsable() {
        ScriptedAction a = ScriptedAction.register(registry, "A");
        ScriptedAction.register(registry, "C");
        Tree tree = new TreeBuilder(registry, new TreeContext()).build(Fixtures.load("includes.bt"));
        assertEquals(NodeStatus.SUCCESS, tree.tickRoot());
        assertEquals(1, a.ticks);
        assertEquals("Main/Work/work/A", tree.find("A").get().path());
    }

    @Test
    public void aSubtreeThatContainsItselfIsRefused() {
        ScriptedAction.register(registry, "A");
        try {
            new TreeBuilder(registry, new TreeContext()).build(Fixtures.load("recursive.bt"));
            fail();
        } catch (BtBuildException expected) {
            assertTrue(expected.getMessage(), expected.getMessage().contains("includes itself"));
        }
    }

    @Test
    public void aFileWithoutMainTreeRunsItsOnlyTreeAndATreeCanBeChosenById() {
        registry.setFallback(spec -> new AlwaysSuccessNode(spec.info()));
        assertEquals("Only", new TreeBuilder(registry, new TreeContext()).build(Fixtures.load("unknown-action.bt")).id());
        assertEquals("Fb", new TreeBuilder(registry, new TreeContext()).build(Fixtures.load("controls.bt"), "Fb").id());
        try {
            new TreeBuilder(registry, new TreeContext()).build(Fixtures.load("controls.bt"), "Nope");
            fail();
        } catch (BtBuildException expected) {
            assertTrue(expected.getMessage(), expected.getMessage().contains("Nope"));
        }
    }

    @Test
    public void anXmlTreeWithoutIdRunsAndIncludesAnotherXmlFile() {
        ScriptedAction a = ScriptedAction.register(registry, "A");
        ScriptedAction c = ScriptedAction.register(registry, "C");
        Tree tree = new TreeBuilder(registry, new TreeContext()).build(Fixtures.load("xml/main.xml"));
        assertEquals("BehaviorTree_0", tree.id());
        assertEquals(NodeStatus.SUCCESS, tree.tickRoot());
        assertEquals(1, a.ticks);
        assertEquals(1, c.ticks);
        assertEquals("BehaviorTree_0/Sequence/Child/C", tree.find("C").get().path());
    }

    @Test
    public void warningsAreReturnedNotThrown() {
        BtLoader.Loaded loaded = new BtLoader().load(Fixtures.resource("decorators.bt"));
        assertTrue(loaded.warnings().toString(), loaded.warnings().stream().anyMatch(w -> w.contains("RetryUntilSuccesful")));
    }
}
