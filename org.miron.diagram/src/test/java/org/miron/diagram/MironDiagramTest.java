package org.miron.diagram;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import java.util.List;
import java.util.Map;

import org.eclipse.sprotty.SEdge;
import org.eclipse.sprotty.SGraph;
import org.eclipse.sprotty.SNode;
import org.junit.Test;

/**
 * Diagrams of the example MIRoN models: the nominal tree with the varpoints' targets highlighted,
 * each variant an alternative under its varpoint (insertion visible), parameters on their ports.
 */
public class MironDiagramTest {

    @Test
    public void intralogisticsVariantsHangBelowTheirTarget() {
        SGraph graph = Diagrams.layout(Diagrams.of(Models.example("intralogistics/intralogistics.miron"), null));
        Map<String, SNode> byId = BtDiagramTest.byId(graph);
        SNode target = byId.get("Main:0");
        assertTrue(target.getCssClasses().contains("varpoint-target"));
        assertTrue(BtDiagramTest.labels(target).contains("◆ task (in)"));
        SNode point = byId.get("Main:0/task");
        assertNotNull(point);
        assertEquals("varpoint", BtDiagramTest.kind(point));
        assertEquals(List.of("◆ task", "in PickDeliverChargeSubtree"), BtDiagramTest.labels(point));
        for (String[] variant : new String[][] { { "pick", "tree:PickDeliverCharge" }, { "deliver", "tree:DeliverCharge" },
                { "dock", "tree:Charge" }, { "pickDeliverCharge", null } }) {
            SNode node = byId.get("Main:0/task/" + variant[0]);
            assertNotNull(variant[0], node);
            assertEquals("variant", BtDiagramTest.kind(node));
            assertEquals(variant[1], ((TreeSNode) node).getLink());
        }
        SNode main = Models.frames(graph).stream().filter(f -> f.getId().equals("tree:Main")).findFirst().orElseThrow();
        assertTrue(Models.edges(main).stream().anyMatch(e -> e.getType().equals("edge:varpoint")
                && e.getSourceId().equals("Main:0") && e.getTargetId().equals("Main:0/task")));
        assertEquals(4, Models.edges(main).stream().filter(e -> e.getType().equals("edge:variant")).count());
        // maxVelocity is bound to the architecture: listed with the parameters.
        assertNotNull(byId.get("parameters/maxVelocity"));
        BtDiagramTest.checkLayout(graph);
    }

    @Test
    public void hospitalShowsInsertionsAndParametersOnPorts() {
        SGraph graph = Diagrams.layout(Diagrams.of(Models.example("hospital-delivery/hospital.miron"), null));
        Map<String, SNode> byId = BtDiagramTest.byId(graph);
        // before bt.fetch, in bt.travel, after the Handover action selected by XPath in bt.mission.
        assertEquals("before fetch", BtDiagramTest.labels(byId.get("Main:0.1/preparation")).get(1));
        assertEquals("in travel", BtDiagramTest.labels(byId.get("Main:0.2/navigation")).get(1));
        assertEquals("after handover", BtDiagramTest.labels(byId.get("Main:0.3/courtesy")).get(1));
        // driveSpeed is bound to drive's max_speed, inflation to every MoveBase's inflation under navigation.
        SNode drive = byId.get("Navigate:0.0");
        assertTrue(drive.getCssClasses().contains("varpoint-target"));
        assertTrue(BtDiagramTest.labels(drive).toString(), BtDiagramTest.labels(drive).contains("max_speed = 0.8 ← driveSpeed"));
        assertTrue(BtDiagramTest.labels(drive).contains("inflation = 0.4 ← inflation"));
        assertNotNull(byId.get("parameters/platformSpeed"));
        assertNotNull(byId.get("parameters/sounds"));
        // Variant trees are linked from the frame whose node they replace.
        List<String> links = Models.edges(graph).stream().map(SEdge::getTargetId).toList();
        assertTrue(links.toString(), links.contains("tree:NavigateCarefully"));
        BtDiagramTest.checkLayout(graph);
    }
}
