package org.miron.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import javax.xml.parsers.DocumentBuilderFactory;

import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

/**
 * `miron render` as a user runs it: SVGs of the examples (tree file, MIRoN model, woven tree) parsed
 * and checked; bad input reported as `miron check` reports it, with nothing written.
 */
public class RenderCommandTest {
    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    @Test
    public void treeFileToSvgFile() throws Exception {
        Path out = temp.getRoot().toPath().resolve("sub/intralogistics.svg");
        assertEquals(0, Cli.exit("render", Cli.ROOT.resolve("examples/intralogistics/intralogistics.bt").toString(),
                "-o", out.toString()));
        List<Element> nodes = nodes(parse(Files.readString(out)));
        // 7 trees, 21 tree nodes.
        assertEquals(21, nodes.size());
        assertTrue(nodes.stream().anyMatch(n -> n.getAttribute("data-id").equals("Main:0")
                && n.getAttribute("data-kind").equals("subtree") && n.getAttribute("data-link").equals("tree:PickDeliverCharge")));
        assertTrue(nodes.stream().anyMatch(n -> n.getAttribute("data-kind").equals("decorator")
                && n.getTextContent().contains("pick_retry") && n.getTextContent().contains("num_attempts = 3")));
    }

    @Test
    public void oneTreeToStandardOutput() throws Exception {
        Cli cli = new Cli();
        assertEquals(0, cli.run("render", Cli.ROOT.resolve("examples/hospital-delivery/hospital.bt").toString(),
                "--tree", "Navigate"));
        List<Element> nodes = nodes(parse(cli.out()));
        assertEquals(List.of("Navigate:0", "Navigate:0.0", "Navigate:0.1"),
                nodes.stream().map(n -> n.getAttribute("data-id")).toList());
    }

    @Test
    public void mironModelShowsVariants() throws Exception {
        Cli cli = new Cli();
        assertEquals(0, cli.run("render", Cli.ROOT.resolve("examples/hospital-delivery/hospital.miron").toString()));
        List<Element> nodes = nodes(parse(cli.out()));
        assertTrue(nodes.stream().anyMatch(n -> n.getAttribute("data-kind").equals("varpoint")
                && n.getTextContent().contains("after handover")));
        assertEquals(3, nodes.stream().filter(n -> n.getAttribute("data-id").startsWith("Main:0.2/navigation/")).count());
    }

    @Test
    public void wovenTreeShowsWhatTheWeaverAdded() throws Exception {
        Path generated = temp.getRoot().toPath().resolve("gen");
        assertEquals(0, Cli.exit("generate", "-o", generated.toString(),
                Cli.ROOT.resolve("examples/hospital-delivery/hospital.miron").toString()));
        Cli cli = new Cli();
        assertEquals(0, cli.run("render", generated.resolve("hospital.ext.xml").toString()));
        List<Element> nodes = nodes(parse(cli.out()));
        List<Element> woven = nodes.stream().filter(n -> n.getAttribute("class").contains("woven")).toList();
        assertTrue(woven.stream().anyMatch(n -> n.getTextContent().contains("VariantAction")));
        assertTrue(woven.stream().anyMatch(n -> n.getTextContent().matches("(?s).*Switch\\d.*")));
        assertTrue(woven.stream().anyMatch(n -> n.getAttribute("data-kind").equals("control")
                && n.getTextContent().contains("Parallel")));
    }

    @Test
    public void brokenFileIsReportedAndNothingWritten() throws IOException {
        Path broken = Cli.write(temp.getRoot().toPath(), "broken.bt",
                "<root>\n  <BehaviorTree ID=\"T\">\n    <Sequence>\n      <Action ID=\"a\"\n  </BehaviorTree>\n</root>\n");
        Path out = temp.getRoot().toPath().resolve("broken.svg");
        Cli cli = new Cli();
        assertEquals(1, cli.run("render", broken.toString(), "-o", out.toString()));
        String first = cli.err.toString().split("\\R")[0];
        assertTrue(first, first.matches(".*broken\\.bt:\\d+:\\d+: error \\[[a-z.-]+\\]: .*"));
        assertFalse(Files.exists(out));
    }

    @Test
    public void usageErrors() {
        Cli cli = new Cli();
        assertEquals(2, cli.run("render", Cli.ROOT.resolve("examples/hospital-delivery/hospital.bt").toString(),
                "--tree", "NoSuchTree"));
        assertTrue(cli.err.toString(), cli.err.toString().contains("no tree 'NoSuchTree' (trees: Main, "));
        assertEquals(2, Cli.exit("render", temp.getRoot().toPath().resolve("missing.bt").toString()));
        assertEquals(2, Cli.exit("render", Cli.ROOT.resolve("examples/hospital-delivery/hospital.roqme").toString()));
    }

    private static Document parse(String svg) throws Exception {
        DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
        factory.setNamespaceAware(true);
        return factory.newDocumentBuilder().parse(new ByteArrayInputStream(svg.getBytes(StandardCharsets.UTF_8)));
    }

    private static List<Element> nodes(Document svg) {
        List<Element> nodes = new ArrayList<>();
        NodeList groups = svg.getElementsByTagName("g");
        for (int i = 0; i < groups.getLength(); i++) {
            Element g = (Element) groups.item(i);
            if (g.hasAttribute("data-id")) {
                nodes.add(g);
            }
        }
        return nodes;
    }
}
