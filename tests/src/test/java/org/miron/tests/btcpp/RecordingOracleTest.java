package org.miron.tests.btcpp;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.NullNode;
import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.executor.NodeStatus;
import org.miron.runtime.Endpoints;
import org.miron.runtime.Json;
import org.miron.runtime.broker.Broker;
import org.miron.runtime.bus.BusClient;
import org.miron.runtime.live.LiveExecutor;
import org.miron.runtime.recording.BtlogReader;
import org.miron.runtime.recording.Recording;
import org.miron.runtime.skill.SkillInterfaceMock;
import org.miron.runtime.skill.SkillTable;
import org.w3c.dom.Element;
import org.w3c.dom.NamedNodeMap;
import org.w3c.dom.NodeList;

/**
 * The oracle for our FileLogger2 writer: the same woven tree (the intralogistics example, version
 * 4) runs one mission on BehaviorTree.CPP 4.8 (miron-btcpp-run --record, the library's own
 * FileLogger2) and on the Java executor (LiveExecutor.record), side by side on one broker and one
 * skill interface mock, and the two .btlog files are compared modulo timing: the same header tree
 * with the same uids, the same sequence of (uid, status) transitions.
 */
public class RecordingOracleTest {
    @ClassRule
    public static TemporaryFolder temp = new TemporaryFolder();
    private static Path tree;

    @BeforeClass
    public static void weave() throws Exception {
        BtcppRunner.assumeBuilt();
        Path out = temp.newFolder("woven").toPath();
        BtcppRunner.weaveV4(out, "intralogistics/intralogistics.miron");
        tree = out.resolve("intralogistics.ext.xml");
    }

    @Test
    public void bothExecutorsRecordTheSameTreeAndTransitions() throws Exception {
        Path libraryLog = temp.getRoot().toPath().resolve("library.btlog");
        Path ourLog = temp.getRoot().toPath().resolve("ours.btlog");
        Endpoints endpoints = Endpoints.freeLoopback();
        try (Broker broker = new Broker(endpoints).start();
                SkillInterfaceMock skills = new SkillInterfaceMock(endpoints.skill(), endpoints.skillEvents(), new SkillTable(Map.of(
                        "*", new SkillTable.Entry(60, "SUCCESS", NullNode.getInstance(), Json.object())))).start();
                BusClient engine = new BusClient("test-engine", endpoints.busIn(), null, List.of(), null).start()) {
            assertTrue(engine.awaitReady(10_000));
            engine.publishRetained("task", "miron.variant.task",
                    "{\"varpoint\":\"task\",\"value\":\"deliver\",\"seq\":1,\"time\":" + System.currentTimeMillis() + "}");
            NodeStatus javaResult;
            try (BtcppRunner runner = new BtcppRunner(List.of(tree.toString(), "--bus", endpoints.busOut(), "--skill-requests",
                    endpoints.request(), "--skill-results", endpoints.skillEvents(), "--period", "20", "--decision-wait", "60000",
                    "--record", libraryLog.toString()));
                    LiveExecutor java = new LiveExecutor(endpoints).build(tree, null).record(ourLog)) {
                // both start on the decision (a first tick without it would take the Switch's default branch)
                long end = System.currentTimeMillis() + 60_000;
                while (!java.variants().snapshot().containsKey("task") && System.currentTimeMillis() < end) {
                    Thread.sleep(10);
                }
                javaResult = java.run(Duration.ofMillis(20));
                JsonNode start = runner.await("start", l -> l.path("event").asText().equals("start"), 60_000);
                assertTrue("the runner started on the decision: " + start, start.path("decisions").asBoolean());
                runner.await("the mission's end", l -> l.path("event").asText().equals("mission"), 60_000);
                runner.await("stop", l -> l.path("event").asText().equals("stop"), 30_000);
            }
            assertEquals(NodeStatus.SUCCESS, javaResult);
        }
        Recording library = BtlogReader.read(libraryLog);
        Recording ours = BtlogReader.read(ourLog);
        assertEquals("the header's tree, uids included", outline(library.treeXml()), outline(ours.treeXml()));
        assertTrue("the library recorded the mission: " + library.transitions().size(), library.transitions().size() > 20);
        assertEquals("the transitions, in order", steps(library), steps(ours));
        assertEquals(0, library.trailingBytes());
        assertEquals(0, ours.trailingBytes());
    }

    /** "uid STATUS", one a transition: the recording without its timing. */
    private static List<String> steps(Recording recording) {
        List<String> steps = new ArrayList<>();
        recording.transitions().forEach(t -> steps.add(t.uid() + " " + t.status()));
        return steps;
    }

    /** The BehaviorTree elements, one line a node: depth, tag, attributes sorted. */
    private static List<String> outline(String xml) throws Exception {
        Element root = DocumentBuilderFactory.newInstance().newDocumentBuilder()
                .parse(new ByteArrayInputStream(xml.getBytes(StandardCharsets.UTF_8))).getDocumentElement();
        List<String> lines = new ArrayList<>();
        NodeList trees = root.getElementsByTagName("BehaviorTree");
        for (int i = 0; i < trees.getLength(); i++) {
            outline((Element) trees.item(i), 0, lines);
        }
        return lines;
    }

    private static void outline(Element e, int depth, List<String> into) {
        TreeMap<String, String> attributes = new TreeMap<>();
        NamedNodeMap map = e.getAttributes();
        for (int i = 0; i < map.getLength(); i++) {
            attributes.put(map.item(i).getNodeName(), map.item(i).getNodeValue());
        }
        into.add("  ".repeat(depth) + e.getTagName() + " " + attributes);
        for (org.w3c.dom.Node c = e.getFirstChild(); c != null; c = c.getNextSibling()) {
            if (c instanceof Element child) {
                outline(child, depth + 1, into);
            }
        }
    }
}
