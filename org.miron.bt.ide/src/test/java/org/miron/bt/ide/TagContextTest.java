package org.miron.bt.ide;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.util.Map;

import org.junit.Test;
import org.miron.bt.ide.contentassist.TagContext;
import org.miron.bt.nodes.NodeDeclaration;
import org.miron.bt.nodes.NodeDeclarations;

/** Where the caret is in a start tag, and what a TreeNodesModel declares, read from text. */
public class TagContextTest {

    private static TagContext at(String textWithCaret) {
        int caret = textWithCaret.indexOf('|');
        return TagContext.at(textWithCaret.replace("|", ""), caret);
    }

    @Test
    public void elementName() {
        TagContext context = at("<root>\n  <Mo|");
        assertEquals(TagContext.Kind.ELEMENT_NAME, context.kind());
        assertEquals("Mo", context.partial());
    }

    @Test
    public void attributeNameSeesTheAttributesAfterTheCaretToo() {
        TagContext context = at("<Action na| ID=\"MoveTo\" x=\"1\"/>");
        assertEquals(TagContext.Kind.ATTRIBUTE_NAME, context.kind());
        assertEquals("Action", context.tag());
        assertEquals("na", context.partial());
        assertEquals(Map.of("ID", "MoveTo", "x", "1"), context.attributes());
    }

    @Test
    public void attributeValue() {
        TagContext context = at("<SubTree ID=\"Go|\"/>");
        assertEquals(TagContext.Kind.ATTRIBUTE_VALUE, context.kind());
        assertEquals("ID", context.attribute());
        assertEquals("Go", context.partial());
    }

    @Test
    public void outsideTags() {
        assertEquals(TagContext.Kind.NONE, at("<Sequence>|").kind());
        assertEquals(TagContext.Kind.NONE, at("</Seq|").kind());
        assertEquals(TagContext.Kind.NONE, at("<!-- a| -->").kind());
        assertEquals(TagContext.Kind.NONE, at("|").kind());
        assertEquals(TagContext.Kind.NONE, TagContext.at("<a", 99).kind());
    }

    @Test
    public void nodesModelDeclarationsWithPorts() {
        Map<String, NodeDeclaration> nodes = NodeDeclarations.parse("<TreeNodesModel><Action ID=\"MoveTo\">"
                + "<input_port name=\"x\">target x</input_port><output_port name=\"done\"/></Action>"
                + "<Decorator ID=\"Rate\"/></TreeNodesModel>");
        assertEquals("Action", nodes.get("MoveTo").kind());
        assertEquals("target x", nodes.get("MoveTo").ports().get("x").description());
        assertEquals("output_port", nodes.get("MoveTo").ports().get("done").direction());
        assertTrue(nodes.get("Rate").ports().isEmpty());
    }

    @Test
    public void aMalformedOrHostileNodesModelDeclaresNothing() {
        assertTrue(NodeDeclarations.parse("<TreeNodesModel><Action ID=\"x\">").isEmpty());
        assertTrue(NodeDeclarations.parse("<!DOCTYPE x [<!ENTITY e SYSTEM \"file:///etc/passwd\">]><TreeNodesModel>"
                + "<Action ID=\"&e;\"/></TreeNodesModel>").isEmpty());
    }
}
