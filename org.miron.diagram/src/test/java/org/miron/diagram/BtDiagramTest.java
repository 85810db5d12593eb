package org.miron.diagram;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.sprotty.SEdge;
import org.eclipse.sprotty.SGraph;
import org.eclipse.sprotty.SLabel;
import org.eclipse.sprotty.SNode;
import org.junit.Test;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.util.BtTrees;

/**
 * Diagrams of BT files checked against the files' own structure: one diagram node per tree node,
 * one child edge per parent and child, kinds from the catalogue and the TreeNodesModel, calls
 * linked, and a layout that is top-down, in document order and free of overlaps.
 */
public class BtDiagramTest {

    @Test
    public void intralogisticsHasOneNodePerTreeNodeAndItsEdges() {
        checkStructure(Models.example("intralogistics/intralogistics.bt"));
    }

    @Test
    public void hospitalHasOneNodePerTreeNodeAndItsEdges() {
        checkStructure(Models.example("hospital-delivery/hospital.bt"));
    }

    @Test
    public void kindsComeFromTheCatalogueAndTheNodesModel() throws Exception {
        Resource file = Models.tree("""
                <root BTCPP_format="4" main_tree_to_execute="T">
                  <BehaviorTree ID="T">
                    <Fallback name="top">
                      <IsBatteryLow/>
                      <RateController hz="2"><Charge level="80"/></RateController>
                      <Inverter><Condition ID="IsDocked"/></Inverter>
                      <Sequence>
                        <Script code="x := 1"/>
                        <AlwaysSuccess/>
                        <SubTree ID="Other" target="{x}"/>
                        <Action ID="Beep"/>
                      </Sequence>
                    </Fallback>
                  </BehaviorTree>
                  <BehaviorTree ID="Other"><Sleep msec="10"/></BehaviorTree>
                  <TreeNodesModel>
                    <Condition ID="IsBatteryLow"/>
                    <Decorator ID="RateController"><input_port name="hz"/></Decorator>
                    <Action ID="Charge"><input_port name="level"/></Action>
                    <Condition ID="IsDocked"/>
                    <Action ID="Beep"/>
                  </TreeNodesModel>
                </root>
                """, ".xml");
        checkStructure(file);
        Map<String, SNode> byId = byId(Diagrams.layout(Diagrams.of(file, null)));
        assertKind(byId, "T:0", "control", "top");
        assertKind(byId, "T:0.0", "condition", "IsBatteryLow");
        assertKind(byId, "T:0.1", "decorator", "RateController");
        assertKind(byId, "T:0.1.0", "action", "Charge");
        assertKind(byId, "T:0.2", "decorator", "Inverter");
        assertKind(byId, "T:0.2.0", "condition", "IsDocked");
        assertKind(byId, "T:0.3", "control", "Sequence");
        assertKind(byId, "T:0.3.0", "builtin", "Script");
        assertKind(byId, "T:0.3.1", "builtin", "AlwaysSuccess");
        assertKind(byId, "T:0.3.2", "subtree", "Other");
        assertKind(byId, "T:0.3.3", "action", "Beep");
        assertKind(byId, "Other:0", "builtin", "Sleep");
        // Port values are labels; the ID of an explicit form is its type, not a port.
        assertTrue(labels(byId.get("T:0.1")).contains("hz = 2"));
        assertTrue(labels(byId.get("T:0.3.2")).contains("target = {x}"));
        assertFalse(labels(byId.get("T:0.3.3")).stream().anyMatch(l -> l.startsWith("ID")));
        assertEquals("tree:Other", ((TreeSNode) byId.get("T:0.3.2")).getLink());
    }

    @Test
    public void subtreeCallsLinkTheirTrees() {
        Resource file = Models.example("intralogistics/intralogistics.bt");
        SGraph graph = Diagrams.layout(Diagrams.of(file, null));
        Map<String, SNode> byId = byId(graph);
        assertEquals("subtree", kind(byId.get("Main:0")));
        assertEquals("tree:PickDeliverCharge", ((TreeSNode) byId.get("Main:0")).getLink());
        Set<String> calls = new HashSet<>();
        for (SEdge edge : Models.edges(graph)) {
            calls.add(edge.getSourceId() + " -> " + edge.getTargetId());
        }
        assertTrue(calls.toString(), calls.contains("tree:Main -> tree:PickDeliverCharge"));
        assertTrue(calls.toString(), calls.contains("tree:Pick -> tree:GoTo"));
        // A called tree is laid out below its caller.
        SNode main = frame(graph, "tree:Main");
        SNode called = frame(graph, "tree:PickDeliverCharge");
        assertTrue(called.getPosition().getY() >= main.getPosition().getY() + main.getSize().getHeight());
    }

    @Test
    public void oneTreeByIdAndTheExpandedRunView() {
        Resource file = Models.example("intralogistics/intralogistics.bt");
        Diagram one = Diagrams.of(file, "Deliver");
        assertEquals(1, one.frames().size());
        assertEquals(null, Diagrams.of(file, "NoSuchTree"));
        // Run view: Main with every call expanded, numbered by index paths like the executor's.
        Diagram run = BtShapes.expanded(file, null);
        Map<String, Shape> shapes = new HashMap<>();
        run.shapes().forEach(s -> shapes.put(s.id(), s));
        assertEquals("PickDeliverChargeSubtree", shapes.get("0").title());
        assertEquals("pick_deliver_charge", shapes.get("0.0").title());
        assertEquals("deliveries", shapes.get("0.0.0").title());
        assertEquals("pick_step", shapes.get("0.0.0.0.0").title());
        assertEquals("objectpick", shapes.get("0.0.0.0.0.0.1.0").title());
        checkLayout(Diagrams.layout(run));
    }

    /**
     * A bushy tree of 500 nodes whose leaves lie at different depths: the nodes of each depth, read
     * left to right, in depth-first (document) order, so no two edges cross — what the layout keeps
     * without ELK's model-order sorting.
     */
    @Test
    public void aWideUnevenTreeIsDrawnInDocumentOrderLayerByLayer() {
        Diagram diagram = LayoutBenchmark.generated(500);
        SGraph graph = Diagrams.layout(diagram);
        checkLayout(graph);
        List<String> preorder = new ArrayList<>();
        diagram.frames().get(0).roots().forEach(root -> preorder(root, preorder));
        Map<String, SNode> byId = byId(graph);
        Map<Integer, List<SNode>> layers = new java.util.TreeMap<>(); // by depth, each in preorder
        for (String id : preorder) {
            assertNotNull(id, byId.get(id));
            layers.computeIfAbsent(id.split("\\.").length, d -> new ArrayList<>()).add(byId.get(id));
        }
        layers.forEach((depth, row) -> {
            for (int i = 1; i < row.size(); i++) {
                assertTrue(row.get(i - 1).getId() + " not left of " + row.get(i).getId(),
                        row.get(i - 1).getPosition().getX() + row.get(i - 1).getSize().getWidth() <= row.get(i).getPosition().getX());
            }
        });
        assertTrue("several layers", layers.size() > 4);
    }

    private static void preorder(Shape shape, List<String> into) {
        into.add(shape.id());
        shape.children().forEach(child -> preorder(child, into));
    }

    private static void checkStructure(Resource file) {
        SGraph graph = Diagrams.layout(Diagrams.of(file, null));
        Map<String, SNode> byId = byId(graph);
        Set<String> expectedEdges = new HashSet<>();
        int treeNodes = 0;
        for (BehaviorTree tree : BtTrees.treesOf(file)) {
            List<TreeNode> roots = tree.getNodes();
            for (int i = 0; i < roots.size(); i++) {
                treeNodes += walk(roots.get(i), BtTrees.runName(tree) + ":" + i, byId, expectedEdges);
            }
        }
        assertEquals("one diagram node per tree node", treeNodes, byId.size());
        Set<String> edges = new HashSet<>();
        for (SNode frame : Models.frames(graph)) {
            for (SEdge edge : Models.edges(frame)) {
                assertEquals("edge:child", edge.getType());
                edges.add(edge.getSourceId() + " -> " + edge.getTargetId());
            }
        }
        assertEquals(expectedEdges, edges);
        checkLayout(graph);
    }

    /** Checks the node of a tree node and its children; returns how many tree nodes it has. */
    private static int walk(TreeNode node, String id, Map<String, SNode> byId, Set<String> edges) {
        SNode shape = byId.get(id);
        assertNotNull("no diagram node " + id + " for " + node.getTag(), shape);
        int count = 1;
        List<TreeNode> children = BtTrees.children(node);
        for (int i = 0; i < children.size(); i++) {
            edges.add(id + " -> " + id + "." + i);
            count += walk(children.get(i), id + "." + i, byId, edges);
        }
        return count;
    }

    /** Top-down, children left to right in document order, no two nodes or frames overlapping. */
    static void checkLayout(SGraph graph) {
        List<SNode> frames = Models.frames(graph);
        assertDisjoint(frames);
        for (SNode frame : frames) {
            List<SNode> nodes = Models.nodes(frame);
            assertDisjoint(nodes);
            Map<String, SNode> byId = new HashMap<>();
            nodes.forEach(n -> byId.put(n.getId(), n));
            for (SNode node : nodes) {
                assertTrue(node.getId() + " outside its frame", node.getPosition().getX() >= 0 && node.getPosition().getY() >= 0
                        && node.getPosition().getX() + node.getSize().getWidth() <= frame.getSize().getWidth()
                        && node.getPosition().getY() + node.getSize().getHeight() <= frame.getSize().getHeight());
            }
            Map<String, List<SNode>> children = new HashMap<>();
            for (SEdge edge : Models.edges(frame)) {
                SNode parent = byId.get(edge.getSourceId());
                SNode child = byId.get(edge.getTargetId());
                assertTrue(child.getId() + " not below " + parent.getId(),
                        child.getPosition().getY() >= parent.getPosition().getY() + parent.getSize().getHeight());
                assertTrue(edge.getId() + " has no route", edge.getRoutingPoints().size() >= 2);
                children.computeIfAbsent(parent.getId(), k -> new ArrayList<>()).add(child);
            }
            children.forEach((parent, list) -> {
                for (int i = 1; i < list.size(); i++) {
                    assertTrue("children of " + parent + " out of order", list.get(i - 1).getPosition().getX()
                            + list.get(i - 1).getSize().getWidth() <= list.get(i).getPosition().getX());
                }
            });
        }
    }

    private static void assertDisjoint(List<SNode> nodes) {
        for (int i = 0; i < nodes.size(); i++) {
            for (int j = i + 1; j < nodes.size(); j++) {
                SNode a = nodes.get(i);
                SNode b = nodes.get(j);
                boolean apart = a.getPosition().getX() + a.getSize().getWidth() <= b.getPosition().getX()
                        || b.getPosition().getX() + b.getSize().getWidth() <= a.getPosition().getX()
                        || a.getPosition().getY() + a.getSize().getHeight() <= b.getPosition().getY()
                        || b.getPosition().getY() + b.getSize().getHeight() <= a.getPosition().getY();
                assertTrue(a.getId() + " overlaps " + b.getId(), apart);
            }
        }
    }

    static Map<String, SNode> byId(SGraph graph) {
        Map<String, SNode> byId = new HashMap<>();
        Models.allNodes(graph).forEach(n -> byId.put(n.getId(), n));
        return byId;
    }

    private static SNode frame(SGraph graph, String id) {
        return Models.frames(graph).stream().filter(f -> f.getId().equals(id)).findFirst().orElseThrow();
    }

    static String kind(SNode node) {
        return node.getType().substring("node:".length());
    }

    static List<String> labels(SNode node) {
        return node.getChildren().stream().filter(SLabel.class::isInstance).map(l -> ((SLabel) l).getText()).toList();
    }

    private static void assertKind(Map<String, SNode> byId, String id, String kind, String title) {
        SNode node = byId.get(id);
        assertNotNull(id, node);
        assertEquals(id, kind, kind(node));
        assertEquals(id, title, labels(node).get(0));
    }
}
