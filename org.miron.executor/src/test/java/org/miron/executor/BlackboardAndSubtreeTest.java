package org.miron.executor;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;
import static org.miron.executor.NodeStatus.SUCCESS;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;

import org.junit.Before;
import org.junit.Test;
import org.miron.executor.decorators.SubTreeNode;

/** Ports, SetBlackboard, booleans, SubTree and SubTreePlus remapping (blackboard.bt). */
public class BlackboardAndSubtreeTest {
    private final ActionRegistry registry = new ActionRegistry();
    /** What each Check node saw, port by port. */
    private final List<Ports> seen = new ArrayList<>();

    @Before
    public void setUp() {
        registry.registerSync("Check", ports -> {
            seen.add(ports);
            return SUCCESS;
        });
    }

    private Tree run(String id) {
        Tree tree = Fixtures.build("blackboard.bt", id, registry, new TreeContext());
        assertEquals(SUCCESS, tree.tickRoot());
        return tree;
    }

    @Test
    public void portsReadLiteralsAndBlackboardEntries() {
        Tree tree = run("Ports");
        Ports ports = seen.get(0);
        assertEquals(Optional.of(42), ports.getInt("braces"));
        assertEquals("${key} is a pointer too", Optional.of(42), ports.getInt("dollar"));
        assertEquals("= means the entry named like the port", Optional.of("42"), ports.getString("answer"));
        assertEquals(Optional.of(-9.33), ports.getDouble("literal"));
        assertEquals(Optional.of("hello world"), ports.getString("text"));
        assertEquals(Optional.empty(), ports.get("absent"));
        assertEquals(Optional.of("42"), tree.blackboard().get("answer"));
        assertEquals(Optional.of("42"), tree.blackboard().get("copy"));
    }

    @Test
    public void aPortWithALiteralThatIsNotANumberIsAnError() {
        run("Ports");
        try {
            seen.get(0).getInt("text");
            fail();
        } catch (BtRuntimeException expected) {
            assertTrue(expected.getMessage(), expected.getMessage().contains("hello world"));
        }
    }

    @Test
    public void booleansAccept01TrueFalseInAnyCase() {
        run("Booleans");
        Ports ports = seen.get(0);
        for (String port : List.of("t1", "t2", "t3", "t4")) {
            assertEquals(port, Optional.of(true), ports.getBoolean(port));
        }
        for (String port : List.of("f1", "f2", "f3")) {
            assertEquals(port, Optional.of(false), ports.getBoolean(port));
        }
        try {
            ports.getBoolean("bad");
            fail("yes is not a boolean");
        } catch (BtRuntimeException expected) {
            assertTrue(expected.getMessage(), expected.getMessage().contains("yes"));
        }
    }

    @Test
    public void subTreeRemapsPlainNamesAndKeepsOtherKeysPrivate() {
        Tree tree = run("SubTreeIsolated");
        assertEquals(Optional.of(7), seen.get(0).getInt("v"));
        assertEquals("result is remapped to outcome", Optional.of("done"), tree.blackboard().get("outcome"));
        assertFalse(tree.blackboard().get("result").isPresent());
        assertFalse("scratch stays in the subtree", tree.blackboard().get("scratch").isPresent());
        SubTreeNode subtree = (SubTreeNode) tree.find("Inner").get();
        assertEquals(Optional.of("private"), subtree.blackboard().get("scratch"));
    }

    @Test
    public void sharedSubTreeUsesTheParentBlackboard() {
        Tree tree = run("SubTreeShared");
        assertEquals(Optional.of(8), seen.get(0).getInt("v"));
        assertEquals(Optional.of("done"), tree.blackboard().get("result"));
        assertEquals(Optional.of("private"), tree.blackboard().get("scratch"));
    }

    @Test
    public void subTreePlusRemapsBracesAndWritesLiterals() {
        Tree tree = run("SubTreePlusRemap");
        assertEquals(Optional.of(11), seen.get(0).getInt("v"));
        assertEquals(Optional.of("done"), tree.blackboard().get("outcome"));
        SubTreeNode subtree = (SubTreeNode) tree.find("Inner").get();
        assertEquals(Map.of("target", "goal", "result", "outcome"), subtree.blackboard().remappings());
        assertEquals("the subtree overwrote its literal", Optional.of("private"), subtree.blackboard().get("scratch"));
        assertFalse(tree.blackboard().get("scratch").isPresent());
    }

    @Test
    public void subTreePlusLiteralIsVisibleInside() {
        Tree tree = Fixtures.build("blackboard.bt", "SubTreePlusRemap", registry, new TreeContext());
        SubTreeNode subtree = (SubTreeNode) tree.find("Inner").get();
        assertEquals("written before the first tick", Optional.of("literal value"), subtree.blackboard().get("scratch"));
    }

    @Test
    public void autoremapMapsEveryKeyTheSubtreeUsesExceptTheExplicitOnes() {
        Tree tree = run("SubTreePlusAutoremap");
        assertEquals(Optional.of(12), seen.get(0).getInt("v"));
        assertEquals(Optional.of("done"), tree.blackboard().get("result"));
        assertFalse("scratch was given a literal, so it is not remapped", tree.blackboard().get("scratch").isPresent());
    }

    @Test
    public void withoutAutoremapTheSubtreeSeesNothing() {
        Tree tree = run("SubTreePlusNoAutoremap");
        assertEquals(Optional.empty(), seen.get(0).get("v"));
        assertFalse(tree.blackboard().get("result").isPresent());
    }

    @Test
    public void aTreeIdUsedAsATagIsASubTree() {
        Tree tree = run("TreeAsTag");
        assertTrue(tree.find("Inner").get() instanceof SubTreeNode);
        assertEquals(Optional.of(14), seen.get(0).getInt("v"));
        assertEquals(Optional.of("done"), tree.blackboard().get("outcome"));
    }

    @Test
    public void aRemappedWriteGoesToTheParentAndAnUnmappedOneStaysLocal() {
        Blackboard parent = Blackboard.create();
        Blackboard child = parent.createChild();
        child.remap("inner", "outer");
        child.set("inner", 1);
        child.set("local", 2);
        assertEquals(Optional.of(1), parent.get("outer"));
        assertEquals(Optional.of(1), child.get("inner"));
        assertFalse(parent.get("local").isPresent());
        parent.set("outer", 3);
        assertEquals(Optional.of(3), child.get("inner"));
    }
}
