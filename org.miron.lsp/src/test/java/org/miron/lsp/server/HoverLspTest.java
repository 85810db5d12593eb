package org.miron.lsp.server;

import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

import org.eclipse.lsp4j.Hover;
import org.eclipse.lsp4j.HoverParams;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.junit.Rule;
import org.junit.Test;

/**
 * Issue 23, item 5: every named thing has a hover, through a real client: trees and nodes named
 * from a .miron, a compact node declared in TreeNodesModel, built-ins of either version, RoQME
 * functions.
 */
public class HoverLspTest {
    @Rule
    public final ExampleSession session = new ExampleSession("intralogistics");

    private String hover(Path file, String text, String after) throws Exception {
        String uri = session.client.open(file, text);
        session.client.awaitDiagnostics(uri, d -> true);
        Hover hover = session.client.server().getTextDocumentService()
                .hover(new HoverParams(new TextDocumentIdentifier(uri), IntralogisticsLspTest.positionAfter(text, after)))
                .get(60, TimeUnit.SECONDS);
        return hover == null || hover.getContents() == null ? "" : hover.getContents().getRight().getValue();
    }

    @Test
    public void treesAndNodesNamedFromTheMiron() throws Exception {
        Path miron = session.workspace.resolve("intralogistics.miron");
        String text = Files.readString(miron);
        String tree = hover(miron, text, "dock : main.Cha");
        assertTrue(tree, tree.contains("BehaviorTree") && tree.contains("Charge") && tree.contains("intralogistics.bt"));
        String node = hover(miron, text, "} in main.PickDeliverChargeSub");
        assertTrue(node, node.contains("SubTreePlus") && node.contains("PickDeliverChargeSubtree")
                && node.contains("intralogistics.bt"));
    }

    @Test
    public void compactDeclaredNodesAndBuiltinsOfBothVersions() throws Exception {
        Path tree = session.workspace.resolve("v4.bt");
        String text = "<root BTCPP_format=\"4\" main_tree_to_execute=\"Main\">\n  <BehaviorTree ID=\"Main\">\n"
                + "    <Sequence>\n      <Script code=\"x := 1\"/>\n      <Repeat num_cycles=\"2\">\n"
                + "        <MoveTo x=\"1\" y=\"2\"/>\n      </Repeat>\n    </Sequence>\n  </BehaviorTree>\n"
                + "  <TreeNodesModel>\n    <Action ID=\"MoveTo\">\n      <input_port name=\"x\">target x (m)</input_port>\n"
                + "      <input_port name=\"y\"/>\n    </Action>\n  </TreeNodesModel>\n</root>\n";
        Files.writeString(tree, text);
        String compact = hover(tree, text, "<MoveTo");
        assertTrue(compact, compact.contains("MoveTo") && compact.contains("target x (m)"));
        String script = hover(tree, text, "<Scri");
        assertTrue(script, script.contains("Script") && script.contains("code"));
        String repeat = hover(tree, text, "<Repe");
        assertTrue(repeat, repeat.contains("Repeat") && repeat.contains("num_cycles"));
        Path v3 = session.workspace.resolve("intralogistics.bt");
        String repeat3 = hover(v3, Files.readString(v3), "<Repe");
        assertTrue(repeat3, repeat3.contains("Repeat") && repeat3.contains("num_cycles"));
    }

    @Test
    public void roqmeFunctions() throws Exception {
        Path roqme = session.workspace.resolve("intralogistics.roqme");
        String text = Files.readString(roqme);
        String count = hover(roqme, text, ":= cou");
        assertTrue(count, count.contains("count(") && count.contains("window"));
    }

    @Test
    public void requirementsAndTheirTemporalOperators() throws Exception {
        Path miron = session.workspace.resolve("intralogistics.miron");
        String text = Files.readString(miron);
        String requirement = hover(miron, text, "requirement rarelySt");
        assertTrue(requirement, requirement.contains("**requirement rarelyStranded**: `never (roqme.BatteryLevel < 1 and "
                + "not roqme.Docked)`") && requirement.contains("with probability at least 0.9"));
        String every = hover(miron, text, "requirement neverStranded : nev");
        assertTrue(every, every.startsWith("never φ: φ holds at no instant of the run"));
        String bounded = hover(miron, text, "implies eventu");
        assertTrue(bounded, bounded.startsWith("eventually within 5 seconds φ: φ holds at some instant before 5 seconds"));
        String always = hover(miron, text, "requirement slowNearPeople : alw");
        assertTrue(always, always.startsWith("always φ: φ holds at every instant of the run"));
    }
}
