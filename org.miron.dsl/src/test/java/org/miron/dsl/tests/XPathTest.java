package org.miron.dsl.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.emf.ecore.resource.Resource;
import org.junit.Test;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.TreeNode;
import org.miron.dsl.bt.BtXPath;
import org.miron.dsl.miron.BtBinding;
import org.miron.dsl.miron.MironModel;
import org.miron.dsl.miron.VariationPoint;

/** XPaths of BT bindings, evaluated on the .bt file and mapped back to BT model objects. */
public class XPathTest {

    private static BtBinding binding(String file, String varpoint) {
        Resource resource = Models.load(new File("src/test/resources/models/miron/valid/" + file));
        MironModel model = (MironModel) resource.getContents().get(0);
        return (BtBinding) model.getVariables().stream().filter(v -> v.getName().equals(varpoint))
                .map(v -> ((VariationPoint) v).getBinding()).findFirst().get();
    }

    @Test
    public void attributeOfTheTargetNode() {
        BtBinding b = binding("ports.miron", "speed");
        BtXPath.Result r = BtXPath.evaluate(b.getXpath(), b.getTargets().get(0));
        assertNull(r.error);
        assertEquals(1, r.selections.size());
        Attribute port = (Attribute) r.selections.get(0).model;
        assertEquals("speed", port.getName());
        assertEquals("0.5", port.getValue());
        assertEquals("move", ((TreeNode) port.eContainer()).getName());
    }

    @Test
    public void absolutePathFromTheDocument() {
        BtBinding b = binding("insertion.miron", "around");
        BtXPath.Result r = BtXPath.evaluate(b.getXpath(), b.getTargets().get(0));
        List<String> names = r.selections.stream().map(s -> ((TreeNode) s.model).getName()).collect(Collectors.toList());
        assertEquals(List.of("greet", "beep"), names);
    }

    @Test
    public void relativeChildPath() {
        BtBinding b = binding("insertion.miron", "retries");
        BtXPath.Result r = BtXPath.evaluate(b.getXpath(), b.getTargets().get(0));
        assertEquals(1, r.selections.size());
        assertTrue(r.selections.get(0).isTreeNode());
        assertEquals("retry", ((TreeNode) r.selections.get(0).model).getName());
    }

    @Test
    public void invalidXPathIsAnErrorNotAnException() {
        BtBinding b = binding("ports.miron", "speed");
        BtXPath.Result r = BtXPath.evaluate("///[", b.getTargets().get(0));
        assertNotNull(r.error);
        assertTrue(r.error, r.error.startsWith("invalid XPath '///['"));
    }
}
