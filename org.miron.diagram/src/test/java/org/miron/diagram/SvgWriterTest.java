package org.miron.diagram;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Map;

import javax.xml.parsers.DocumentBuilderFactory;

import org.junit.Test;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

/** The SVG is a well-formed document holding every node of the diagram, whatever the labels hold. */
public class SvgWriterTest {

    @Test
    public void exampleSvgHoldsEveryNodeWithItsKind() throws Exception {
        Diagram diagram = Diagrams.of(Models.example("hospital-delivery/hospital.bt"), null);
        Document svg = parse(Diagrams.svg(diagram));
        assertEquals("svg", svg.getDocumentElement().getTagName());
        NodeList groups = svg.getElementsByTagName("g");
        int nodes = 0;
        for (int i = 0; i < groups.getLength(); i++) {
            Element g = (Element) groups.item(i);
            if (g.hasAttribute("data-id")) {
                nodes++;
                Shape shape = diagram.shapes().stream().filter(s -> s.id().equals(g.getAttribute("data-id"))).findFirst()
                        .orElseThrow();
                assertEquals(shape.kind().word(), g.getAttribute("data-kind"));
                assertTrue(g.getAttribute("class").contains("node-" + shape.kind().word()));
            }
        }
        assertEquals(diagram.shapes().size(), nodes);
        assertTrue(svg.getElementsByTagName("path").getLength() > 0);
    }

    @Test
    public void hostileTextStaysWellFormed() throws Exception {
        Diagram diagram = new Diagram("x");
        Frame frame = new Frame("tree:<&\"]]>", "tree <&\"]]>\u0001");
        Shape root = new Shape("a\"<b", ShapeKind.CONTROL, "name <&> \"q\" ]]> \u0000\u0007\uFFFF end", "type\u001b");
        root.ports().add(new Shape.Port("p&", "v<\n\t>", "vp\"x"));
        root.children().add(new Shape("c&", ShapeKind.ACTION, "😀 emoji", "action").link("tree:<&\"]]>"));
        frame.roots().add(root);
        diagram.frames().add(frame);
        String text = SvgWriter.write(DiagramLayout.layout(diagram), Map.of("c&", List.of("status-running")));
        Document svg = parse(text);
        assertTrue(svg.getDocumentElement().getTextContent().contains("name <&> \"q\" ]]>  end"));
        assertTrue(svg.getDocumentElement().getTextContent().contains("😀 emoji"));
        NodeList groups = svg.getElementsByTagName("g");
        boolean running = false;
        for (int i = 0; i < groups.getLength(); i++) {
            Element g = (Element) groups.item(i);
            running |= g.getAttribute("data-id").equals("c&") && g.getAttribute("class").contains("status-running");
        }
        assertTrue(running);
    }

    @Test
    public void emptyDiagramIsStillADocument() throws Exception {
        Document svg = parse(Diagrams.svg(new Diagram("empty")));
        assertEquals("svg", svg.getDocumentElement().getTagName());
    }

    static Document parse(String svg) throws Exception {
        DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
        factory.setNamespaceAware(true);
        return factory.newDocumentBuilder().parse(new ByteArrayInputStream(svg.getBytes(StandardCharsets.UTF_8)));
    }
}
