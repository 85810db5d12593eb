package org.miron.tests.btcpp;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.NullNode;
import java.io.ByteArrayInputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.TreeSet;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.After;
import org.junit.Before;
import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Endpoints;
import org.miron.runtime.Json;
import org.miron.runtime.broker.Broker;
import org.miron.runtime.bus.BusClient;
import org.miron.runtime.live.LiveExecutor;
import org.miron.runtime.skill.SkillInterfaceMock;
import org.miron.runtime.skill.SkillTable;
import org.miron.testkit.runtime.GrootClient;
import org.w3c.dom.Element;
import org.w3c.dom.NamedNodeMap;
import org.w3c.dom.NodeList;

/**
 * The oracle for our Groot2 server: the same woven tree (the intralogistics example) on
 * BehaviorTree.CPP 4.8's own Groot2Publisher (miron-btcpp-run --groot) and on ours (the Java
 * executor's), the same requests to both, the answers compared modulo timing: the tree with its
 * uids, the status snapshot's layout, blackboard names, hooks, breakpoint notices, error replies.
 */
public class GrootOracleTest {
    @ClassRule
    public static TemporaryFolder temp = new TemporaryFolder();
    private static Path tree;
    private static final ObjectMapper JSON = new ObjectMapper();

    private final Endpoints endpoints = Endpoints.freeLoopback();
    private Broker broker;
    private SkillInterfaceMock skills;
    private BusClient engine;
    private BtcppRunner runner;
    private LiveExecutor java;
    private Thread javaRobot;
    private GrootClient library;
    private GrootClient ours;
    private int requestId = 0x7A000000;

    @BeforeClass
    public static void weave() throws Exception {
        BtcppRunner.assumeBuilt();
        Path out = temp.newFolder("woven").toPath();
        BtcppRunner.weaveV4(out, "intralogistics/intralogistics.miron");
        tree = out.resolve("intralogistics.ext.xml");
    }

    @Before
    public void start() throws Exception {
        broker = new Broker(endpoints).start();
        // MoveTo takes a minute: both trees stay in the same place while they are compared
        skills = new SkillInterfaceMock(endpoints.skill(), endpoints.skillEvents(), new SkillTable(Map.of(
                "MoveTo", new SkillTable.Entry(60_000, "SUCCESS", NullNode.getInstance(), Json.object()),
                "*", new SkillTable.Entry(20, "SUCCESS", NullNode.getInstance(), Json.object())))).start();
        engine = new BusClient("test-engine", endpoints.busIn(), null, List.of(), null).start();
        assertTrue(engine.awaitReady(10_000));
        engine.publishRetained("task", "miron.variant.task",
                "{\"varpoint\":\"task\",\"value\":\"deliver\",\"seq\":1,\"time\":" + System.currentTimeMillis() + "}");
        int libraryPort = GrootClient.freePortPair();
        runner = new BtcppRunner(List.of(tree.toString(), "--bus", endpoints.busOut(), "--skill-requests",
                endpoints.request(), "--skill-results", endpoints.skillEvents(), "--period", "20",
                "--trace", "--groot", Integer.toString(libraryPort)));
        runner.await("start", l -> l.path("event").asText().equals("start"), 30_000);
        library = new GrootClient(libraryPort);
        int ourPort = GrootClient.freePortPair();
        java = new LiveExecutor(endpoints).build(tree, null).serveGroot(ourPort);
        javaRobot = new Thread(() -> java.run(Duration.ofMillis(20)), "groot-oracle-java-robot");
        javaRobot.start();
        ours = new GrootClient(ourPort);
        assertNotNull("BT.CPP's publisher answers: " + runner.stderr(), library.requestUntilAnswered('T', 20_000));
        assertNotNull(ours.requestUntilAnswered('T', 20_000));
    }

    @After
    public void stop() throws Exception {
        for (AutoCloseable c : new AutoCloseable[] { library, ours, java, runner, engine, skills, broker }) {
            if (c != null) {
                c.close();
            }
        }
        if (javaRobot != null) {
            javaRobot.join(5000);
        }
    }

    /** Both answers to the same request. */
    private List<List<byte[]>> both(char type, String... parts) {
        List<byte[]> message = new ArrayList<>();
        message.add(GrootClient.header((byte) type, ++requestId));
        for (String part : parts) {
            message.add(part.getBytes(StandardCharsets.UTF_8));
        }
        return raw(message);
    }

    private List<List<byte[]>> raw(List<byte[]> message) {
        List<byte[]> a = library.raw(message);
        List<byte[]> b = ours.raw(message);
        assertNotNull("BT.CPP answers: " + runner.stderr(), a);
        assertNotNull("we answer", b);
        return List.of(a, b);
    }

    private static String text(byte[] part) {
        return GrootClient.text(part);
    }

    @Test
    public void theTreeWithItsUidsIsTheLibrarys() throws Exception {
        List<List<byte[]>> replies = both('T');
        Files.writeString(Path.of(System.getProperty("java.io.tmpdir"), "groot-library.xml"), text(replies.get(0).get(1)));
        Files.writeString(Path.of(System.getProperty("java.io.tmpdir"), "groot-ours.xml"), text(replies.get(1).get(1)));
        assertArrayEquals("the reply header, tree id included", replies.get(0).get(0), replies.get(1).get(0));
        Element libraryRoot = parse(replies.get(0).get(1));
        Element ourRoot = parse(replies.get(1).get(1));
        assertEquals(trees(libraryRoot), trees(ourRoot));
        // every node type the tree uses has the library's model, its port names included
        Map<String, String> libraryModels = models(libraryRoot);
        Map<String, String> ourModels = models(ourRoot);
        assertEquals("the node types the tree uses", 9, ourModels.size());
        for (Map.Entry<String, String> model : ourModels.entrySet()) {
            assertEquals(model.getKey(), libraryModels.get(model.getKey()), model.getValue());
        }
    }

    private static Element parse(byte[] xml) throws Exception {
        return DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(new ByteArrayInputStream(xml)).getDocumentElement();
    }

    /** The BehaviorTree elements, one line a node: depth, tag, attributes sorted. */
    private static List<String> trees(Element root) {
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

    /** TreeNodesModel: "Kind ID" → its sorted port names with directions. */
    private static Map<String, String> models(Element root) {
        Map<String, String> models = new TreeMap<>();
        Element model = (Element) root.getElementsByTagName("TreeNodesModel").item(0);
        for (org.w3c.dom.Node c = model.getFirstChild(); c != null; c = c.getNextSibling()) {
            if (c instanceof Element m) {
                TreeSet<String> ports = new TreeSet<>();
                for (org.w3c.dom.Node p = m.getFirstChild(); p != null; p = p.getNextSibling()) {
                    if (p instanceof Element port && port.getTagName().endsWith("_port")) {
                        ports.add(port.getTagName() + " " + port.getAttribute("name"));
                    }
                }
                models.put(m.getTagName() + " " + m.getAttribute("ID"), ports.toString());
            }
        }
        return models;
    }

    /** The uids of the status snapshot in order (the statuses themselves depend on timing). */
    private static List<Integer> statusUids(byte[] snapshot) {
        ByteBuffer in = ByteBuffer.wrap(snapshot).order(ByteOrder.LITTLE_ENDIAN);
        List<Integer> uids = new ArrayList<>();
        while (in.remaining() >= 3) {
            uids.add(in.getShort() & 0xFFFF);
            in.get();
        }
        return uids;
    }

    @Test
    public void theStatusSnapshotHasTheLibrarysLayout() throws Exception {
        List<List<byte[]>> replies = both('S');
        assertEquals(2, replies.get(0).size());
        assertEquals(replies.get(0).get(1).length, replies.get(1).get(1).length);
        assertEquals(statusUids(replies.get(0).get(1)), statusUids(replies.get(1).get(1)));
        // both trees settle in the same place (MoveTo on the deliver branch, a minute long): the
        // same statuses, IDLE-after-a-status included
        long end = System.currentTimeMillis() + 10_000;
        do {
            Thread.sleep(100);
            replies = both('S');
        } while (!Arrays.equals(replies.get(0).get(1), replies.get(1).get(1)) && System.currentTimeMillis() < end);
        assertEquals(statuses(replies.get(0).get(1)), statuses(replies.get(1).get(1)));
    }

    private static Map<Integer, Integer> statuses(byte[] snapshot) {
        ByteBuffer in = ByteBuffer.wrap(snapshot).order(ByteOrder.LITTLE_ENDIAN);
        Map<Integer, Integer> statuses = new TreeMap<>();
        while (in.remaining() >= 3) {
            statuses.put(in.getShort() & 0xFFFF, (int) in.get());
        }
        return statuses;
    }

    private static String hook(int uid, int mode, int position, String desired, boolean once) {
        return "{\"enabled\":true,\"uid\":" + uid + ",\"mode\":" + mode + ",\"once\":" + once + ",\"desired_status\":\""
                + desired + "\",\"position\":" + position + "}";
    }

    /** Both replies alike: the same number of parts, each the same bytes (the dump sorted by uid). */
    private static void assertSame(String what, List<List<byte[]>> replies) {
        List<String> a = new ArrayList<>();
        List<String> b = new ArrayList<>();
        replies.get(0).forEach(p -> a.add(Arrays.toString(p) + " " + text(p)));
        replies.get(1).forEach(p -> b.add(Arrays.toString(p) + " " + text(p)));
        assertEquals(what, a, b);
    }

    private JsonNode[] dumps() throws Exception {
        List<List<byte[]>> replies = both('D');
        JsonNode[] sorted = new JsonNode[2];
        for (int i = 0; i < 2; i++) {
            List<JsonNode> hooks = new ArrayList<>();
            JSON.readTree(replies.get(i).get(1)).forEach(hooks::add);
            hooks.sort((x, y) -> Integer.compare(x.path("uid").asInt(), y.path("uid").asInt()));
            sorted[i] = JSON.valueToTree(hooks);
        }
        return sorted;
    }

    @Test
    public void hooksAreInsertedListedAndRemovedAsTheLibraryDoes() throws Exception {
        // objectpick (15) and objectdrop (21) are not on the running branch: nothing pauses
        assertSame("insert", both('I', "[" + hook(15, 0, 0, "SKIPPED", false) + "," + hook(21, 1, 1, "FAILURE", true) + "]"));
        assertSame("update", both('I', hook(15, 1, 0, "SUCCESS", true)));
        assertSame("an unknown uid", both('I', hook(999, 0, 0, "SKIPPED", false)));
        JsonNode[] dumps = dumps();
        assertEquals(2, dumps[0].size());
        assertEquals(dumps[0], dumps[1]);
        assertSame("a POST hook is not found as POST", both('R', "{\"uid\":21,\"position\":1}"));
        assertSame("unlock an unknown uid", both('U', "{\"uid\":999,\"position\":0,\"desired_status\":\"SUCCESS\",\"remove_when_done\":false}"));
        assertSame("remove an unknown uid", both('R', "{\"uid\":999,\"position\":0}"));
        assertSame("remove", both('R', "{\"uid\":21,\"position\":0}"));
        dumps = dumps();
        assertEquals(1, dumps[0].size());
        assertEquals(dumps[0], dumps[1]);
        assertSame("disable all", both('X'));
        dumps = dumps();
        assertEquals(dumps[0], dumps[1]);
        assertEquals(false, dumps[0].get(0).path("enabled").asBoolean());
        assertSame("remove all", both('A'));
        assertEquals("[]", dumps()[1].toString());
    }

    @Test
    public void aBreakpointIsReachedNotifiedAndUnlockedAsOnTheLibrary() throws Exception {
        library.drainNotices();
        ours.drainNotices();
        // VariantAction (3) runs for ever: every tick asks its hook
        assertSame("insert", both('I', hook(3, 0, 0, "SKIPPED", false)));
        List<byte[]> a = library.awaitNotice(5000);
        List<byte[]> b = ours.awaitNotice(5000);
        assertNotNull("BT.CPP notifies", a);
        assertNotNull("we notify", b);
        assertEquals(2, a.size());
        assertEquals(a.size(), b.size());
        assertEquals(6, a.get(0).length);
        assertEquals(a.get(0).length, b.get(0).length);
        assertEquals("protocol and type", Arrays.toString(Arrays.copyOf(a.get(0), 2)), Arrays.toString(Arrays.copyOf(b.get(0), 2)));
        assertEquals("3", text(a.get(1)));
        assertEquals(text(a.get(1)), text(b.get(1)));
        assertNull("paused: no second notice", library.awaitNotice(300));
        assertNull(ours.awaitNotice(10));
        // the status snapshot is still served while paused, statuses alike where the trees are
        List<List<byte[]>> statuses = both('S');
        assertEquals(statusUids(statuses.get(0).get(1)), statusUids(statuses.get(1).get(1)));
        assertSame("unlock", both('U', "{\"uid\":3,\"position\":0,\"desired_status\":\"SKIPPED\",\"remove_when_done\":true}"));
        // the tick thread removes the hook once it goes on, after the reply: wait for it on both
        JsonNode[] dumps = dumps();
        for (int i = 0; i < 50 && (dumps[0].size() > 0 || dumps[1].size() > 0); i++) {
            Thread.sleep(20);
            dumps = dumps();
        }
        assertEquals("[]", dumps[0].toString());
        assertEquals(dumps[0], dumps[1]);
    }

    @Test
    public void malformedRequestsGetTheLibrarysErrorReplies() throws Exception {
        assertSame("short header", raw(List.of(new byte[] { 2, 'T', 0, 0, 0 })));
        assertSame("unknown type", both('Z'));
        assertSame("blackboard without names", both('B'));
        assertSame("insert without a hook", both('I'));
        assertSame("unlock in three parts", both('U', "a", "b"));
        assertSame("recording without a command", both('r'));
        assertSame("remove without a hook", both('R'));
        assertSame("an unknown recording command", both('r', "pause"));
        List<List<byte[]>> tree = both('T');
        assertArrayEquals("still serving", tree.get(0).get(0), tree.get(1).get(0));
    }

    @Test
    public void blackboardsAreNamedAndDumpedAsTheLibraryDumpsThem() throws Exception {
        Element root = parse(both('T').get(0).get(1));
        List<String> names = new ArrayList<>();
        NodeList trees = root.getElementsByTagName("BehaviorTree");
        for (int i = 0; i < trees.getLength(); i++) {
            Element t = (Element) trees.item(i);
            names.add(t.getAttribute("_fullpath").isEmpty() ? t.getAttribute("ID") : t.getAttribute("_fullpath"));
        }
        names.add("nope");
        List<List<byte[]>> replies = both('B', String.join(";", names));
        JsonNode library = MsgPackReader.read(replies.get(0).get(1));
        JsonNode ours = MsgPackReader.read(replies.get(1).get(1));
        assertEquals(fieldNames(library), fieldNames(ours));
        for (String name : fieldNames(library)) {
            assertEquals(name, fieldNames(library.get(name)), fieldNames(ours.get(name)));
        }
        assertEquals("the values too (text, as the tree's ports are)", library, ours);
        assertSame("nothing found", both('B', "nope"));
    }

    @Test
    public void withoutRequestsForFiveSecondsBothDisableTheirHooksAndTheNextRequestEnablesThem() throws Exception {
        assertSame("insert", both('I', hook(3, 0, 0, "SKIPPED", false)));
        assertNotNull(library.awaitNotice(5000));
        assertNotNull(ours.awaitNotice(5000));
        // Groot2 goes quiet: after the library's 5 s both trees go on, without a notice. That is
        // waited for, not slept (under load a heartbeat thread can be late, and a request before
        // it came would leave the tree paused): a decision sent while both are paused switches
        // the task, so the library's trace shows Charge starting once its tree goes on.
        Thread.sleep(1000); // the lines the library printed before it paused are in by then
        int traced = runner.lines().size();
        engine.publishRetained("task", "miron.variant.task",
                "{\"varpoint\":\"task\",\"value\":\"dock\",\"seq\":2,\"time\":" + System.currentTimeMillis() + "}");
        runner.await("the library's tree going on to Charge", l -> l.path("node").asText().startsWith("Charge")
                && l.path("to").asText().equals("RUNNING"), 20_000, traced);
        for (long end = System.currentTimeMillis() + 20_000; java.groot().clientAlive() && System.currentTimeMillis() < end;) {
            Thread.sleep(20);
        }
        assertFalse("ours: hooks disabled", java.groot().clientAlive());
        library.drainNotices();
        ours.drainNotices();
        assertNull("BT.CPP: hooks disabled", library.awaitNotice(300));
        assertNull("ours: hooks disabled", ours.awaitNotice(10));
        JsonNode[] dumps = dumps(); // a request: Groot2 is back
        assertEquals(dumps[0].get(0).path("uid"), dumps[1].get(0).path("uid"));
        assertNotNull("BT.CPP: enabled again", library.awaitNotice(5000));
        assertNotNull("ours: enabled again", ours.awaitNotice(5000));
        assertSame("remove all", both('A'));
    }

    @Test
    public void recordingAnswersAsTheLibrary() throws Exception {
        List<List<byte[]>> started = both('r', "start");
        assertEquals(2, started.get(0).size());
        assertEquals(started.get(0).size(), started.get(1).size());
        long libraryClock = Long.parseLong(text(started.get(0).get(1)));
        long ourClock = Long.parseLong(text(started.get(1).get(1)));
        assertTrue("both send the wall clock in microseconds", Math.abs(libraryClock - ourClock) < 5_000_000);
        engine.publishRetained("task", "miron.variant.task",
                "{\"varpoint\":\"task\",\"value\":\"dock\",\"seq\":2,\"time\":" + System.currentTimeMillis() + "}");
        Thread.sleep(1000);
        List<List<byte[]>> transitions = both('t');
        for (List<byte[]> reply : transitions) {
            assertEquals(2, reply.size());
            assertTrue("transitions recorded: " + reply.get(1).length, reply.get(1).length > 0);
            assertEquals(0, reply.get(1).length % 9);
        }
        assertSame("stop", both('r', "stop"));
    }

    private static List<String> fieldNames(JsonNode object) {
        List<String> names = new ArrayList<>();
        if (object != null) {
            object.fieldNames().forEachRemaining(names::add);
        }
        return names;
    }
}
