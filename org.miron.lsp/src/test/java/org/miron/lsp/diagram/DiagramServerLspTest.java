package org.miron.lsp.diagram;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

import javax.xml.parsers.DocumentBuilderFactory;

import org.junit.After;
import org.junit.Before;
import org.junit.Test;
import org.miron.lsp.diagram.DiagramClient.Received;
import org.miron.testkit.Examples;
import org.miron.testkit.Folders;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;

/**
 * The diagram server over LSP, as sprotty-vscode talks to it: a model request is answered with the
 * file's diagram, an edit with an update, broken text keeps the last diagram and says so, opening a
 * node reveals its source, and SubTree calls expand and collapse.
 */
public class DiagramServerLspTest {
    private Path workspace;
    private DiagramClient client;
    private Path bt;
    private String text;
    private String uri;

    @Before
    public void start() throws Exception {
        workspace = Examples.copy("hospital-delivery");
        client = new DiagramClient();
        client.initialize(workspace);
        bt = workspace.resolve("hospital.bt");
        text = Files.readString(bt);
        uri = client.open(bt, text);
    }

    @After
    public void stop() throws Exception {
        client.close();
        Folders.delete(workspace);
    }

    @Test
    public void aModelRequestGetsOneNodePerTreeNodeWithItsLabels() throws Exception {
        JsonObject graph = requestModel("one");
        Map<String, JsonObject> nodes = treeNodes(graph);
        assertEquals(xmlTreeNodes(text), nodes.size());
        List<String> titles = titles(nodes);
        for (String name : List.of("mission", "fetch", "handover", "drive", "recover", "announce")) {
            assertTrue(name + " in " + titles, titles.contains(name));
        }
        // The edges go from parent to child: mission (a Sequence) has its five children.
        String mission = idOf(nodes, "mission");
        long children = children(graph).stream().flatMap(frame -> children(frame).stream())
                .filter(e -> "edge:child".equals(type(e))
                && mission.equals(e.get("sourceId").getAsString())).count();
        assertEquals(5, children);
    }

    @Test
    public void anEditUpdatesTheDiagram() throws Exception {
        requestModel("edit");
        int mark = client.mark();
        client.change(uri, text.replace("name=\"handover\"", "name=\"handOverParcel\""));
        Received update = client.await(mark, r -> "updateModel".equals(r.kind()), "updateModel");
        List<String> titles = titles(treeNodes(update.action().getAsJsonObject("newRoot")));
        assertTrue(titles.toString(), titles.contains("handOverParcel"));
        assertFalse(titles.toString(), titles.contains("handover"));
    }

    @Test
    public void theFirstModelOfAFileIsFittedToTheViewAndAnUpdateIsNot() throws Exception {
        int mark = client.mark();
        JsonObject graph = requestModel("fit");
        Received fit = client.await(mark, r -> "fit".equals(r.params().get("clientId").getAsString())
                && "fit".equals(r.kind()), "fit");
        Received set = client.await(mark, r -> "setModel".equals(r.kind()), "setModel");
        assertTrue("the fit after the model", client.indexOf(fit) > client.indexOf(set));
        assertFitsEveryFrame(fit, graph);

        // A keystroke: an update, which keeps the user's zoom and scroll.
        int edit = client.mark();
        client.change(uri, text.replace("name=\"handover\"", "name=\"handOverParcel\""));
        Received update = client.await(edit, r -> "updateModel".equals(r.kind()), "updateModel");
        // The panel follows another file: its first model is fitted again.
        Path miron = workspace.resolve("hospital.miron");
        String mironUri = client.open(miron, Files.readString(miron));
        int follow = client.mark();
        client.send("fit", requestModelAction(mironUri));
        Received mironSet = client.await(follow, r -> "setModel".equals(r.kind()), "setModel of the .miron");
        Received mironFit = client.await(follow, r -> "fit".equals(r.kind()), "fit of the .miron");
        assertTrue(client.indexOf(mironFit) > client.indexOf(mironSet));
        assertFitsEveryFrame(mironFit, mironSet.action().getAsJsonObject("newRoot"));
        for (Received after : client.between(client.indexOf(update), client.indexOf(mironSet))) {
            assertFalse("no fit after an update: " + after, "fit".equals(after.kind()));
        }
    }

    /** A fit, not animated, of every tree frame of the graph (not of a selection). */
    private static void assertFitsEveryFrame(Received fit, JsonObject graph) {
        List<String> frames = children(graph).stream().filter(c -> "tree".equals(type(c)))
                .map(c -> c.get("id").getAsString()).toList();
        assertFalse(frames.isEmpty());
        List<String> ids = new ArrayList<>();
        fit.action().getAsJsonArray("elementIds").forEach(id -> ids.add(id.getAsString()));
        assertEquals(frames, ids);
        assertFalse(fit.action().get("animate").getAsBoolean());
        assertEquals(1.0, fit.action().get("maxZoom").getAsDouble(), 0);
    }

    @Test
    public void brokenTextKeepsTheLastDiagramAndSaysSo() throws Exception {
        requestModel("broken");
        int mark = client.mark();
        client.change(uri, text.replace("</Sequence>\n  </BehaviorTree>\n\n  <BehaviorTree ID=\"FetchMedicine\">",
                "</Sequece>\n  </BehaviorTree>\n\n  <BehaviorTree ID=\"FetchMedicine\">"));
        Received status = client.await(mark, r -> "serverStatus".equals(r.kind()), "serverStatus");
        JsonObject action = status.action();
        assertEquals("error", action.get("severity").getAsString().toLowerCase());
        assertTrue(action.toString(), action.get("message").getAsString().contains("hospital.bt does not parse"));
        for (Received before : client.between(mark, client.indexOf(status) + 1)) {
            assertFalse("no model while broken: " + before, "setModel".equals(before.kind()) || "updateModel".equals(before.kind()));
        }
        // Fixed again: an update of the kept diagram, and the error cleared.
        int fixed = client.mark();
        client.change(uri, text.replace("name=\"recover\"", "name=\"recoverAgain\""));
        Received update = client.await(fixed, r -> "updateModel".equals(r.kind()), "updateModel");
        assertTrue(titles(treeNodes(update.action().getAsJsonObject("newRoot"))).contains("recoverAgain"));
        Received ok = client.await(fixed, r -> "serverStatus".equals(r.kind()), "serverStatus OK");
        assertEquals("ok", ok.action().get("severity").getAsString().toLowerCase());
    }

    @Test
    public void openingANodeRevealsItsSource() throws Exception {
        Map<String, JsonObject> nodes = treeNodes(requestModel("open"));
        int mark = client.mark();
        JsonObject open = new JsonObject();
        open.addProperty("kind", "open");
        open.addProperty("elementId", idOf(nodes, "handover"));
        client.send("open", open);
        Received reveal = client.await(mark, r -> r.method().equals("diagram/openInTextEditor"), "openInTextEditor");
        JsonObject location = reveal.params().getAsJsonObject("location");
        assertEquals(uri, location.get("uri").getAsString());
        JsonObject start = location.getAsJsonObject("range").getAsJsonObject("start");
        JsonObject end = location.getAsJsonObject("range").getAsJsonObject("end");
        String[] lines = text.split("\n", -1);
        int line = 0;
        while (!lines[line].contains("name=\"handover\"")) {
            line++;
        }
        assertEquals(line, start.get("line").getAsInt());
        assertEquals(lines[line].indexOf('<'), start.get("character").getAsInt());
        assertEquals(line, end.get("line").getAsInt());
        assertEquals(lines[line].indexOf("/>") + 2, end.get("character").getAsInt());
        assertTrue(reveal.params().get("forceOpen").getAsBoolean());
    }

    @Test
    public void subTreeCallsExpandAndCollapse() throws Exception {
        Map<String, JsonObject> nodes = treeNodes(requestModel("expand"));
        String fetch = idOf(nodes, "fetch");
        assertFalse(nodes.get(fetch).get("expanded").getAsBoolean());
        int before = nodes.size();

        int mark = client.mark();
        client.send("expand", collapseExpand("expandIds", fetch));
        Map<String, JsonObject> expanded = treeNodes(client.await(mark, r -> "updateModel".equals(r.kind()), "updateModel")
                .action().getAsJsonObject("newRoot"));
        assertTrue(expanded.get(fetch).get("expanded").getAsBoolean());
        // FetchMedicine's three nodes drawn below the call, as well as in their own frame.
        assertEquals(before + 3, expanded.size());
        List<String> below = new ArrayList<>();
        expanded.forEach((id, node) -> {
            if (id.startsWith(fetch + ".")) {
                below.add(title(node));
            }
        });
        assertEquals(List.of("fetchSequence", "grasp", "openDrawer"), below.stream().sorted().toList());

        mark = client.mark();
        client.send("expand", collapseExpand("collapseIds", fetch));
        Map<String, JsonObject> collapsed = treeNodes(client.await(mark, r -> "updateModel".equals(r.kind()), "updateModel")
                .action().getAsJsonObject("newRoot"));
        assertEquals(before, collapsed.size());
        assertFalse(collapsed.get(fetch).get("expanded").getAsBoolean());
    }

    @Test
    public void aMironModelShowsItsVariationPointsOnTheTree() throws Exception {
        Path miron = workspace.resolve("hospital.miron");
        String mironUri = client.open(miron, Files.readString(miron));
        int mark = client.mark();
        client.send("miron", requestModelAction(mironUri));
        JsonObject graph = client.await(mark, r -> "setModel".equals(r.kind()), "setModel").action().getAsJsonObject("newRoot");
        Map<String, JsonObject> nodes = treeNodes(graph);
        assertTrue(nodes.values().stream().anyMatch(n -> n.has("cssClasses")
                && n.getAsJsonArray("cssClasses").toString().contains("varpoint-target")));
        assertTrue(nodes.values().stream().anyMatch(n -> "node:varpoint".equals(type(n))));
    }

    private JsonObject requestModel(String clientId) throws InterruptedException {
        int mark = client.mark();
        client.send(clientId, requestModelAction(uri));
        Received set = client.await(mark, r -> "setModel".equals(r.kind())
                && r.params().get("clientId").getAsString().equals(clientId), "setModel");
        assertEquals("the answer to the request", "client_1", set.action().get("responseId").getAsString());
        return set.action().getAsJsonObject("newRoot");
    }

    private static JsonObject requestModelAction(String sourceUri) {
        JsonObject options = new JsonObject();
        options.addProperty("sourceUri", sourceUri);
        options.addProperty("diagramType", "miron-diagram");
        options.addProperty("needsClientLayout", "true");
        JsonObject action = new JsonObject();
        action.addProperty("kind", "requestModel");
        action.add("options", options);
        action.addProperty("requestId", "client_1");
        return action;
    }

    private static JsonObject collapseExpand(String which, String id) {
        JsonObject action = new JsonObject();
        action.addProperty("kind", "collapseExpand");
        JsonArray ids = new JsonArray();
        ids.add(id);
        action.add(which, ids);
        action.add(which.equals("expandIds") ? "collapseIds" : "expandIds", new JsonArray());
        return action;
    }

    /** The diagram's tree nodes (not the frames), by id. */
    static Map<String, JsonObject> treeNodes(JsonObject graph) {
        Map<String, JsonObject> nodes = new TreeMap<>();
        for (JsonObject frame : children(graph)) {
            for (JsonObject element : children(frame)) {
                if (type(element).startsWith("node:")) {
                    nodes.put(element.get("id").getAsString(), element);
                }
            }
        }
        return nodes;
    }

    static List<JsonObject> children(JsonObject element) {
        List<JsonObject> children = new ArrayList<>();
        if (element.has("children")) {
            for (JsonElement child : element.getAsJsonArray("children")) {
                children.add(child.getAsJsonObject());
            }
        }
        return children;
    }

    static String type(JsonObject element) {
        return element.get("type").getAsString();
    }

    static String title(JsonObject node) {
        return children(node).stream().filter(l -> "label:title".equals(type(l))).findFirst()
                .map(l -> l.get("text").getAsString()).orElse(null);
    }

    static List<String> titles(Map<String, JsonObject> nodes) {
        return nodes.values().stream().map(DiagramServerLspTest::title).toList();
    }

    private static String idOf(Map<String, JsonObject> nodes, String title) {
        String id = nodes.entrySet().stream().filter(e -> title.equals(title(e.getValue()))).map(Map.Entry::getKey)
                .findFirst().orElse(null);
        assertNotNull("a node titled " + title, id);
        return id;
    }

    /** The element count inside the file's BehaviorTree elements, read with the JDK's XML parser. */
    private static int xmlTreeNodes(String xml) throws Exception {
        org.w3c.dom.Document document = DocumentBuilderFactory.newInstance().newDocumentBuilder()
                .parse(new ByteArrayInputStream(xml.getBytes(StandardCharsets.UTF_8)));
        NodeList trees = document.getElementsByTagName("BehaviorTree");
        int count = 0;
        for (int i = 0; i < trees.getLength(); i++) {
            count += ((Element) trees.item(i)).getElementsByTagName("*").getLength();
        }
        return count;
    }
}
