package org.miron.bt.ide;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import java.util.List;
import java.util.Map;

import org.junit.Test;
import org.miron.bt.nodes.NodeDeclaration;
import org.miron.bt.nodes.NodeDeclarations;
import org.miron.bt.nodes.NodeCatalogue;
import org.miron.bt.nodes.NodeModel;
import org.miron.bt.nodes.PortModel;

/**
 * The catalogue written as BehaviorTree.CPP's {@code <TreeNodesModel>} reads back, through the
 * parser that reads users' declarations, as the same nodes, kinds, ports and directions.
 */
public class CatalogueManifestTest {

    @Test
    public void theManifestOfEachVersionReadsBackAsTheCatalogue() {
        for (int version : List.of(NodeCatalogue.V3, NodeCatalogue.V4)) {
            Map<String, NodeDeclaration> declared = NodeDeclarations.parse(NodeCatalogue.treeNodesModel(version));
            int expected = 0;
            for (NodeModel node : NodeCatalogue.in(version)) {
                if (node.explicitForm() && node.kind() != org.miron.bt.nodes.NodeKind.SUBTREE) {
                    continue;
                }
                expected++;
                NodeDeclaration declaration = declared.get(node.tag());
                assertNotNull(node.tag() + " missing in the version-" + version + " manifest", declaration);
                assertEquals(node.tag(), node.kind().xmlName(), declaration.kind());
                List<PortModel> ports = node.ports(version).stream().filter(p -> !p.name().equals("ID")).toList();
                assertEquals(node.tag() + " ports", ports.stream().map(PortModel::name).toList(),
                        List.copyOf(declaration.ports().keySet()));
                for (PortModel port : ports) {
                    NodeDeclaration.Port read = declaration.ports().get(port.name());
                    assertEquals(port.direction().xmlName(), read.direction());
                    assertEquals(port.description() == null ? "" : port.description(), read.description());
                }
            }
            assertEquals(expected, declared.size());
            assertTrue("version " + version + ": " + declared.keySet(), expected > 25);
        }
        assertTrue(NodeCatalogue.treeNodesModel(4).contains(
                "<input_port name=\"then_skip\" type=\"bool\" default=\"true\">"));
    }
}
