package org.miron.runtime.groot;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.ByteArrayInputStream;
import java.net.URISyntaxException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.After;
import org.junit.Test;
import org.miron.executor.ActionRegistry;
import org.miron.executor.NodeStatus;
import org.miron.executor.Tree;
import org.miron.executor.TreeBuilder;
import org.miron.executor.TreeContext;
import org.miron.testkit.runtime.GrootClient;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

/** Our Groot2 server for a tree of the Java executor, through a real ZeroMQ client on the loopback. */
public class GrootServerTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    private final List<String> steps = new ArrayList<>();
    private final AtomicInteger ids = new AtomicInteger();
    private final ExecutorService ticking = Executors.newSingleThreadExecutor();
    private CompletableFuture<NodeStatus> drive;
    private Tree tree;
    private GrootServer server;
    private GrootClient client;

    private void start(String file) throws Exception {
        ActionRegistry registry = new ActionRegistry();
        registry.registerSync("Step", ports -> {
            synchronized (steps) {
                steps.add(ports.raw("name"));
            }
            return NodeStatus.SUCCESS;
        });
        registry.registerFuture("Drive", ports -> drive = new CompletableFuture<>());
        tree = new TreeBuilder(registry, new TreeContext()).build(resource(file));
        int port = GrootClient.freePortPair();
        server = GrootServer.start(tree, port);
        client = new GrootClient(port);
        assertTrue("the notice subscriber reaches the publisher", client.awaitSubscriber(10_000));
    }

    private static Path resource(String name) throws URISyntaxException {
        return Path.of(GrootServerTest.class.getResource("/groot/" + name).toURI());
    }

    @After
    public void stop() throws Exception {
        if (server != null) {
            server.close();
        }
        if (client != null) {
            client.close();
        }
        ticking.shutdownNow();
        ticking.awaitTermination(5, TimeUnit.SECONDS);
    }

    private List<byte[]> ask(char type, String... parts) {
        List<byte[]> reply = client.request(type, parts);
        assertNotNull("a reply to " + type, reply);
        return reply;
    }

    private void assertOk(List<byte[]> reply, char type) {
        assertEquals("reply header: " + GrootClient.text(reply.get(0)), 22, reply.get(0).length);
        assertEquals(2, reply.get(0)[0]);
        assertEquals((byte) type, reply.get(0)[1]);
    }

    private static void assertError(List<byte[]> reply, String reason) {
        assertEquals(2, reply.size());
        assertEquals("error", GrootClient.text(reply.get(0)));
        assertEquals(reason, GrootClient.text(reply.get(1)));
    }

    private static String hook(int uid, int mode, int position, String desired, boolean once) {
        return "{\"enabled\":true,\"uid\":" + uid + ",\"mode\":" + mode + ",\"once\":" + once + ",\"desired_status\":\""
                + desired + "\",\"position\":" + position + "}";
    }

    private JsonNode dump() throws Exception {
        List<byte[]> reply = ask('D');
        assertOk(reply, 'D');
        return JSON.readTree(reply.get(1));
    }

    @Test
    public void theFullTreeIsNumberedDepthFirstWithEverySubtreeAndCaseAsTheLibraryDoes() throws Exception {
        start("main.xml");
        byte[] header = GrootClient.header((byte) 'T', 0x01020304);
        List<byte[]> reply = client.raw(List.of(header));
        assertNotNull(reply);
        assertEquals(2, reply.size());
        byte[] replyHeader = reply.get(0);
        assertEquals(22, replyHeader.length);
        assertArrayEquals(header, java.util.Arrays.copyOf(replyHeader, 6));
        assertArrayEquals(GrootProtocol.treeId(), java.util.Arrays.copyOfRange(replyHeader, 6, 22));
        Document xml = DocumentBuilderFactory.newInstance().newDocumentBuilder()
                .parse(new ByteArrayInputStream(reply.get(1)));
        NodeList trees = xml.getElementsByTagName("BehaviorTree");
        assertEquals(3, trees.getLength());
        String[][] expected = { { "Main", "" }, { "Work", "work" }, { "Work", "Work::10" } };
        for (int i = 0; i < 3; i++) {
            Element t = (Element) trees.item(i);
            assertEquals(expected[i][0], t.getAttribute("ID"));
            assertEquals(expected[i][1], t.getAttribute("_fullpath"));
        }
        // uids in document order of the main tree, subtrees expanded where they are called
        List<String> order = new ArrayList<>();
        NodeList all = xml.getElementsByTagName("*");
        for (int i = 0; i < all.getLength(); i++) {
            Element e = (Element) all.item(i);
            if (e.hasAttribute("_uid")) {
                order.add(e.getAttribute("_uid") + ":" + e.getTagName() + ":" + (e.hasAttribute("name") ? e.getAttribute("name") : e.getAttribute("_fullpath")));
            }
        }
        assertEquals(List.of("1:Sequence:Sequence", "2:Script:Script", "3:SubTree:work", "6:Switch2:Switch2", "7:Step:a",
                "8:Step:b", "9:Step:c", "10:SubTree:Work::10", "4:Sequence:Sequence", "5:Step:inner", "11:Sequence:Sequence",
                "12:Step:inner"), order);
        Element work = (Element) xml.getElementsByTagName("SubTree").item(0);
        assertEquals("Work", work.getAttribute("ID"));
        assertEquals("{count}", work.getAttribute("target"));
        Element inner = (Element) ((Element) trees.item(1)).getElementsByTagName("Step").item(0);
        assertEquals("false", inner.getAttribute("_skipIf"));
        Element models = (Element) xml.getElementsByTagName("TreeNodesModel").item(0);
        List<String> actions = new ArrayList<>();
        NodeList declared = models.getElementsByTagName("Action");
        for (int i = 0; i < declared.getLength(); i++) {
            actions.add(((Element) declared.item(i)).getAttribute("ID"));
        }
        assertEquals(List.of("Script", "Step"), actions);
        assertTrue(GrootClient.text(reply.get(1)).startsWith("<root BTCPP_format=\"4\">\n    <BehaviorTree ID=\"Main\" _fullpath=\"\">\n"
                + "        <Sequence name=\"Sequence\" _uid=\"1\">\n"));
    }

    @Test
    public void theStatusSnapshotIsPackedSubtreeBySubtreeWithIdleFromTheLastStatus() throws Exception {
        start("main.xml");
        List<byte[]> before = ask('S');
        assertOk(before, 'S');
        ByteBuffer idle = ByteBuffer.wrap(before.get(1)).order(ByteOrder.LITTLE_ENDIAN);
        List<Integer> uids = new ArrayList<>();
        for (int i = 0; i < 12; i++) {
            uids.add((int) idle.getShort());
            assertEquals(0, idle.get());
        }
        assertEquals(List.of(1, 2, 3, 6, 7, 8, 9, 10, 4, 5, 11, 12), uids);
        assertEquals(NodeStatus.SUCCESS, tree.tickRoot());
        ByteBuffer after = ByteBuffer.wrap(ask('S').get(1)).order(ByteOrder.LITTLE_ENDIAN);
        int[] status = new int[13];
        for (int i = 0; i < 12; i++) {
            int uid = after.getShort();
            status[uid] = after.get();
        }
        assertEquals("the root, reset after SUCCESS: 10 + SUCCESS", 12, status[1]);
        assertEquals("case b never ran", 0, status[8]);
        assertEquals(12, status[7]);
        assertEquals(12, status[12]);
    }

    @Test
    public void blackboardsAreAnsweredBySubtreeNameInMessagePack() throws Exception {
        start("main.xml");
        tree.tickRoot();
        List<byte[]> reply = ask('B', "Main;nope");
        assertOk(reply, 'B');
        // {"Main": {"count": 1}}
        byte[] expected = { (byte) 0x81, (byte) 0xA4, 'M', 'a', 'i', 'n', (byte) 0x81, (byte) 0xA5, 'c', 'o', 'u', 'n', 't', 1 };
        assertArrayEquals(expected, reply.get(1));
        assertArrayEquals("nothing found: null", new byte[] { (byte) 0xC0 }, ask('B', "nope").get(1));
        assertArrayEquals("an empty blackboard: null", new byte[] { (byte) 0x81, (byte) 0xA8, 'W', 'o', 'r', 'k', ':', ':', '1', '0', (byte) 0xC0 },
                ask('B', "Work::10").get(1));
        assertError(client.request('B'), "must be 2 parts message");
    }

    @Test
    public void hooksAreInsertedDumpedAndRemovedAsTheLibraryKeepsThem() throws Exception {
        start("main.xml");
        assertOk(ask('I', "[" + hook(5, 0, 0, "SKIPPED", false) + "," + hook(7, 1, 1, "FAILURE", true) + "]"), 'I');
        assertOk(ask('I', hook(99, 0, 0, "SKIPPED", false)), 'I'); // unknown uid: accepted, not inserted
        JsonNode hooks = dump();
        assertEquals(2, hooks.size());
        assertEquals("{\"desired_status\":\"SKIPPED\",\"enabled\":true,\"mode\":0,\"once\":false,\"position\":0,\"uid\":5}",
                hooks.get(0).toString());
        assertEquals(1, hooks.get(1).path("position").asInt()); // listed as POST...
        assertError(ask('R', "{\"uid\":7,\"position\":1}"), "Node ID not found"); // ...found only as PRE
        assertOk(ask('R', "{\"uid\":7,\"position\":0}"), 'R');
        assertError(ask('R', "{\"uid\":99,\"position\":0}"), "Node ID not found");
        assertError(ask('U', "{\"uid\":99,\"position\":0,\"desired_status\":\"SUCCESS\",\"remove_when_done\":false}"),
                "Node ID not found");
        assertEquals(1, dump().size());
        assertOk(ask('A'), 'A');
        assertEquals(0, dump().size());
    }

    @Test
    public void aBreakpointPausesOnlyTheTickThreadUntilUnlockedWithTheDesiredStatus() throws Exception {
        start("main.xml");
        ask('I', hook(5, 0, 0, "SKIPPED", false));
        Future<NodeStatus> run = ticking.submit(tree::tickRoot);
        List<byte[]> notice = client.awaitNotice(5000);
        assertNotNull("BREAKPOINT_REACHED on the PUB", notice);
        assertEquals(2, notice.size());
        assertEquals(6, notice.get(0).length);
        assertEquals('N', notice.get(0)[1]);
        assertEquals("5", GrootClient.text(notice.get(1)));
        Thread.sleep(200);
        assertFalse("paused", run.isDone());
        // the server still answers while the tree waits
        ByteBuffer status = ByteBuffer.wrap(ask('S').get(1)).order(ByteOrder.LITTLE_ENDIAN);
        status.position(2 * 3); // uid 3, the SubTree work
        assertEquals(3, status.getShort());
        assertEquals("the SubTree runs", 1, status.get());
        assertOk(ask('U', "{\"uid\":5,\"position\":0,\"desired_status\":\"FAILURE\",\"remove_when_done\":true}"), 'U');
        assertEquals(NodeStatus.FAILURE, run.get(5, TimeUnit.SECONDS));
        assertFalse("the node was not ticked", steps.contains("inner"));
        assertEquals("removed when done", 0, dump().size());
    }

    @Test
    public void aResultThatArrivesWhileThePauseLastsIsSeenWhenTheTreeGoesOn() throws Exception {
        start("drive.xml");
        assertEquals(NodeStatus.RUNNING, tree.tickRoot());
        ask('I', hook(2, 0, 0, "SKIPPED", false)); // Drive, running: hooked again on the next tick
        Future<NodeStatus> run = ticking.submit(tree::tickRoot);
        assertNotNull(client.awaitNotice(5000));
        drive.complete(NodeStatus.SUCCESS); // the skill's result comes in meanwhile
        assertFalse(run.isDone());
        ask('U', "{\"uid\":2,\"position\":0,\"desired_status\":\"SKIPPED\",\"remove_when_done\":false}");
        assertEquals(NodeStatus.SUCCESS, run.get(5, TimeUnit.SECONDS));
        assertEquals(List.of("after"), steps);
    }

    @Test
    public void aReplaceHookForcesTheResultAndPublishesTheNoticeToo() throws Exception {
        start("main.xml");
        ask('I', hook(5, 1, 0, "FAILURE", false));
        assertEquals(NodeStatus.FAILURE, tree.tickRoot());
        assertFalse(steps.contains("inner"));
        List<byte[]> notice = client.awaitNotice(2000);
        assertNotNull(notice);
        assertEquals("5", GrootClient.text(notice.get(1)));
        assertEquals("kept: not once", 1, dump().size());
        // a breakpoint changed into a replacement lets its paused tick go
        ask('I', hook(5, 0, 0, "SKIPPED", false));
        Future<NodeStatus> run = ticking.submit(tree::tickRoot);
        client.drainNotices();
        Thread.sleep(100);
        assertFalse("paused: " + (run.isDone() ? run.get() + " " + steps + " " + dump() : ""), run.isDone());
        ask('I', hook(5, 1, 0, "SUCCESS", false));
        assertEquals(NodeStatus.SUCCESS, run.get(5, TimeUnit.SECONDS));
        assertEquals("only the second SubTree's inner (uid 12) ticked", List.of("a", "inner"), steps);
    }

    @Test
    public void aPostHookReplacingAPausedBreakpointLetsTheTreeGoOn() throws Exception {
        start("main.xml");
        ask('I', hook(5, 0, 0, "SKIPPED", false));
        Future<NodeStatus> run = ticking.submit(tree::tickRoot);
        assertNotNull(client.awaitNotice(5000));
        ask('I', hook(5, 1, 1, "FAILURE", false)); // POST: not found as such, so a new hook takes the node
        assertEquals("the old breakpoint let its tick go: inner ticked", NodeStatus.SUCCESS, run.get(5, TimeUnit.SECONDS));
        assertEquals(1, dump().get(0).path("position").asInt());
        assertEquals("the new hook (a REPLACE, asked before the tick) forces FAILURE", NodeStatus.FAILURE, tree.tickRoot());
    }

    @Test
    public void withoutRequestsTheHeartbeatDisablesTheHooksAndTheNextRequestEnablesThem() throws Exception {
        start("main.xml");
        server.heartbeatDelay(Duration.ofMillis(400));
        ask('I', hook(5, 0, 0, "SKIPPED", false));
        Future<NodeStatus> run = ticking.submit(tree::tickRoot);
        assertNotNull(client.awaitNotice(5000));
        // Groot2 is gone: no request for 400 ms releases the tree, which ticks the node
        assertEquals(NodeStatus.SUCCESS, run.get(5, TimeUnit.SECONDS));
        assertEquals("both inner nodes ticked", List.of("inner", "a", "inner"), steps);
        ask('S'); // Groot2 is back
        Thread.sleep(100);
        assertTrue("enabled again after a request", dump().get(0).path("enabled").asBoolean());
        ask('X');
        assertFalse("DISABLE_ALL_HOOKS", dump().get(0).path("enabled").asBoolean());
    }

    @Test
    public void malformedRequestsGetTheLibrarysErrorReplyAndTheServerGoesOn() throws Exception {
        start("main.xml");
        assertError(client.raw(List.of(new byte[] { 2, 'T', 0, 0, 0 })), "wrong request header");
        assertError(client.raw(List.of(new byte[] { 2, 'T', 0, 0, 0, 0, 0 })), "wrong request header");
        assertError(client.request('Z'), "Request not recognized");
        assertError(client.request('I'), "must be 2 parts message");
        assertError(client.request('U', "a", "b"), "must be 2 parts message");
        assertEquals("error", GrootClient.text(ask('I', "{not json").get(0)));
        assertEquals("error", GrootClient.text(ask('I', "{\"uid\":5}").get(0)));
        assertEquals("error", GrootClient.text(ask('I', hook(5, 0, 0, "MAYBE", false)).get(0)));
        assertEquals("error", GrootClient.text(ask('I', "42").get(0)));
        assertEquals("error", GrootClient.text(ask('U', "{\"uid\":\"five\"}").get(0)));
        assertEquals("error", GrootClient.text(ask('R', "").get(0)));
        assertEquals(0, dump().size());
        assertOk(ask('T'), 'T');
    }

    @Test
    public void transitionsAreRecordedNineBytesEach() throws Exception {
        start("main.xml");
        List<byte[]> started = ask('r', "start");
        assertOk(started, 'r');
        long now = Long.parseLong(GrootClient.text(started.get(1)));
        assertTrue(Math.abs(now / 1000 - System.currentTimeMillis()) < 60_000);
        tree.tickRoot();
        byte[] transitions = ask('t').get(1);
        assertTrue(transitions.length > 0);
        assertEquals(0, transitions.length % 9);
        ByteBuffer first = ByteBuffer.wrap(transitions).order(ByteOrder.LITTLE_ENDIAN);
        first.position(6);
        assertEquals("the root starts first", 1, first.getShort());
        assertEquals(1, first.get());
        assertEquals("taken", 0, ask('t').get(1).length);
        assertEquals(1, ask('r', "stop").size());
        tree.tickRoot();
        assertEquals(0, ask('t').get(1).length);
        assertNull(client.awaitNotice(50));
    }
}
