package org.miron.executor;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;
import static org.miron.executor.NodeStatus.FAILURE;
import static org.miron.executor.NodeStatus.RUNNING;
import static org.miron.executor.NodeStatus.SUCCESS;

import java.util.List;

import org.junit.Before;
import org.junit.Test;

/**
 * User-registered control nodes and decorators (builtins.bt), written explicitly
 * ({@code <Decorator ID="Twice">}, {@code <Control ID="LastOnly">}) or compactly ({@code <Twice>}).
 */
public class CustomNodesTest {
    private final ActionRegistry registry = new ActionRegistry();
    private ScriptedAction a;
    private ScriptedAction b;

    /** A custom decorator: ticks its child a second time within the tick when the first succeeds. */
    static final class TwiceNode extends DecoratorNode {
        TwiceNode(NodeInfo info, Node child) {
            super(info, child);
        }

        @Override
        protected NodeStatus tick() {
            setStatus(RUNNING);
            NodeStatus first = child.executeTick();
            if (first.isCompleted()) {
                resetChild();
            }
            if (first != SUCCESS) {
                return first;
            }
            NodeStatus second = child.executeTick();
            if (second.isCompleted()) {
                resetChild();
            }
            return second;
        }
    }

    /** A custom control node: ticks only its last child. */
    static final class LastOnlyNode extends ControlNode {
        LastOnlyNode(NodeInfo info, List<Node> children) {
            super(info, children);
        }

        @Override
        protected NodeStatus tick() {
            setStatus(RUNNING);
            NodeStatus status = tickChild(children.size() - 1);
            if (status.isCompleted()) {
                haltChildren();
            }
            return status;
        }
    }

    @Before
    public void setUp() {
        a = ScriptedAction.register(registry, "A");
        b = ScriptedAction.register(registry, "B");
    }

    private Tree tree(String id) {
        return Fixtures.build("builtins.bt", id, registry, new TreeContext(new FakeClock()));
    }

    @Test
    public void aDecoratorRegisteredInJavaRunsForTheExplicitForm() {
        registry.registerDecorator("Twice", TwiceNode::new);
        Tree tree = tree("CustomDecorator");
        assertEquals(TwiceNode.class, tree.root().getClass());
        assertEquals("CustomDecorator/twice", tree.root().path());
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals(2, a.ticks);
        a.returns(FAILURE);
        assertEquals(FAILURE, tree.tickRoot());
        assertEquals(3, a.ticks);
        a.returns(RUNNING);
        assertEquals(RUNNING, tree.tickRoot());
    }

    @Test
    public void aCompactElementWithOneChildUsesTheRegisteredDecorator() {
        registry.registerDecorator("Twice", TwiceNode::new);
        Tree tree = tree("CompactDecorator");
        assertEquals(TwiceNode.class, tree.root().getClass());
        assertEquals("CompactDecorator/Twice", tree.root().path());
        assertEquals(SUCCESS, tree.tickRoot());
        assertEquals(2, a.ticks);
    }

    @Test
    public void aCompactDecoratorWithTwoChildrenIsRejected() {
        registry.registerDecorator("Twice", TwiceNode::new);
        try {
            tree("CompactDecoratorTwoChildren");
            fail("a decorator has one child");
        } catch (BtBuildException e) {
            assertTrue(e.getMessage(), e.getMessage().startsWith("CompactDecoratorTwoChildren/Twice: "));
            assertTrue(e.getMessage(), e.getMessage().contains("exactly one child"));
        }
    }

    @Test
    public void aControlRegisteredInJavaGetsItsChildrenInBothForms() {
        registry.registerControl("LastOnly", LastOnlyNode::new);
        for (String id : List.of("CustomControl", "CompactControl")) {
            Tree tree = tree(id);
            assertEquals(LastOnlyNode.class, tree.root().getClass());
            assertEquals(2, tree.root().children().size());
            b.returns(FAILURE);
            assertEquals(SUCCESS, tree.tickRoot());
        }
        assertEquals(2, a.ticks);
        assertEquals(0, b.ticks);
    }

    @Test
    public void anUnregisteredCompactNodeIsABuildErrorNamingItsPath() {
        try {
            tree("Unregistered");
            fail("nothing is registered for RateController");
        } catch (BtBuildException e) {
            assertTrue(e.getMessage(), e.getMessage().startsWith(
                    "Unregistered/seq/RateController: no control node or decorator is registered for ID 'RateController'"));
        }
    }

    @Test
    public void anUnregisteredExplicitControlIsABuildErrorNamingItsPath() {
        registry.registerDecorator("LastOnly", TwiceNode::new);
        try {
            tree("CustomControl");
            fail("LastOnly is a decorator, not a control node");
        } catch (BtBuildException e) {
            assertTrue(e.getMessage(), e.getMessage().startsWith("CustomControl/LastOnly: no control node is registered for ID 'LastOnly'"));
        }
    }

    @Test
    public void anUnregisteredDecoratorIsABuildErrorNamingItsPath() {
        registry.registerControl("Throttle", LastOnlyNode::new);
        try {
            tree("UnregisteredDecorator");
            fail("Throttle is a control node, not a decorator");
        } catch (BtBuildException e) {
            assertTrue(e.getMessage(), e.getMessage().startsWith("UnregisteredDecorator/Throttle: no decorator is registered for ID 'Throttle'"));
        }
    }
}
