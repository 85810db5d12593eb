package org.miron.executor;

import static org.junit.Assert.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.bt.nodes.NodeKind;

/** The tick hook (BT.CPP's pre-tick callback) and the registration names monitors such as Groot2 read. */
public class TickHookTest {
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();

    private final List<String> ticked = new ArrayList<>();
    private final List<String> asked = new ArrayList<>();

    private Tree build() throws Exception {
        Path file = tmp.getRoot().toPath().resolve("t.xml");
        Files.writeString(file, "<root BTCPP_format=\"4\"><BehaviorTree ID=\"Main\"><Sequence>"
                + "<Step name=\"one\"/><Action ID=\"Step\" name=\"two\" _skipIf=\"true\"/><Step name=\"three\"/>"
                + "<Inverter><AlwaysFailure/></Inverter></Sequence></BehaviorTree>"
                + "<TreeNodesModel><Action ID=\"Step\"/></TreeNodesModel></root>");
        ActionRegistry registry = new ActionRegistry().registerSync("Step", ports -> {
            ticked.add(ports.raw("name"));
            return NodeStatus.SUCCESS;
        });
        return new TreeBuilder(registry, new TreeContext()).build(file);
    }

    @Test
    public void theHookIsAskedBeforeUnfinishedNodesWithoutADecidingPreconditionAndMayReplaceTheTick() throws Exception {
        Tree tree = build();
        tree.context().setTickHook(node -> {
            asked.add(node.name());
            return node.name().equals("three") ? NodeStatus.FAILURE : node.name().equals("one") ? NodeStatus.SKIPPED : null;
        });
        assertEquals(NodeStatus.FAILURE, tree.tickRoot());
        assertEquals("two was skipped by its pre-condition before any hook", List.of("Sequence", "one", "three"), asked);
        assertEquals("SKIPPED lets one tick; FAILURE replaces three's tick", List.of("one"), ticked);
        tree.context().setTickHook(null);
        assertEquals(NodeStatus.SUCCESS, tree.tickRoot());
        assertEquals(List.of("one", "one", "three"), ticked);
    }

    @Test
    public void nodesKnowTheNameAndKindBehaviorTreeCppRegistersThemUnder() throws Exception {
        List<String> seen = new ArrayList<>();
        for (Node node : build().nodes()) {
            seen.add(node.element() + ":" + node.kind());
        }
        assertEquals(List.of("Sequence:" + NodeKind.CONTROL, "Step:" + NodeKind.ACTION, "Step:" + NodeKind.ACTION,
                "Step:" + NodeKind.ACTION, "Inverter:" + NodeKind.DECORATOR, "AlwaysFailure:" + NodeKind.ACTION), seen);
    }
}
