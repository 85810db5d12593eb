package org.miron.tests.btcpp;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.NullNode;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.function.Predicate;
import org.junit.After;
import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Endpoints;
import org.miron.runtime.Json;
import org.miron.runtime.broker.Broker;
import org.miron.runtime.bus.BusClient;
import org.miron.runtime.skill.SkillInterfaceMock;
import org.miron.runtime.skill.SkillTable;

/**
 * miron-btcpp-run (real BehaviorTree.CPP 4.8.2 with the MIRoN plugin) on the woven intralogistics
 * tree against the real broker and the mock SmartSoft skill interface, over loopback sockets: it
 * follows the engine's decisions from the bus (the last-value cache's at start), pushes the skills
 * with their ports, survives malformed bus messages and a broker restart, and aborts the skill of a
 * branch it leaves.
 */
public class LiveWireTest {
    @ClassRule
    public static TemporaryFolder temp = new TemporaryFolder();
    private static Path tree;
    private static Path hospital;

    private final Endpoints endpoints = Endpoints.freeLoopback();
    private Broker broker;
    private SkillInterfaceMock skills;
    private BusClient engine;
    private BtcppRunner runner;
    private long seq;

    @BeforeClass
    public static void weave() throws Exception {
        BtcppRunner.assumeBuilt();
        Path out = temp.newFolder("woven").toPath();
        BtcppRunner.weaveV4(out, "intralogistics/intralogistics.miron");
        tree = out.resolve("intralogistics.ext.xml");
        BtcppRunner.weaveV4(out, "hospital-delivery/hospital.miron");
        hospital = out.resolve("hospital.ext.xml");
    }

    private void start(long moveToMs) throws Exception {
        broker = new Broker(endpoints).start();
        skills = new SkillInterfaceMock(endpoints.skill(), endpoints.skillEvents(), new SkillTable(Map.of(
                "MoveTo", new SkillTable.Entry(moveToMs, "SUCCESS", NullNode.getInstance(), Json.object()),
                "*", new SkillTable.Entry(50, "SUCCESS", NullNode.getInstance(), Json.object())))).start();
        engine = new BusClient("test-engine", endpoints.busIn(), null, List.of(), null).start();
        assertTrue("the broker subscribes to the test's output", engine.awaitReady(10_000));
    }

    private BtcppRunner runner() throws Exception {
        return new BtcppRunner(List.of(tree.toString(), "--bus", endpoints.busOut(), "--skill-requests",
                endpoints.request(), "--skill-results", endpoints.skillEvents(), "--period", "20", "--repeat"));
    }

    private void decide(String task) {
        engine.publishRetained("task", "miron.variant.task",
                "{\"varpoint\":\"task\",\"value\":\"" + task + "\",\"seq\":" + (++seq) + ",\"time\":" + System.currentTimeMillis() + "}");
    }

    @After
    public void stop() throws Exception {
        if (runner != null) {
            runner.close();
        }
        if (engine != null) {
            engine.close();
        }
        if (skills != null) {
            skills.close();
        }
        if (broker != null) {
            broker.close();
        }
    }

    private static Predicate<JsonNode> moveTo(double x, double y) {
        return skill -> skill.path("name").asText().equals("MoveTo")
                && skill.path("in-attribute").path("x").asDouble() == x && skill.path("in-attribute").path("y").asDouble() == y;
    }

    /** Waits for a push-skill the mock received. */
    private JsonNode awaitPushed(String what, Predicate<JsonNode> p) throws InterruptedException {
        long end = System.currentTimeMillis() + 20_000;
        while (System.currentTimeMillis() < end) {
            for (JsonNode skill : skills.pushed()) {
                if (p.test(skill)) {
                    return skill;
                }
            }
            Thread.sleep(20);
        }
        throw new AssertionError("no push-skill " + what + " reached the skill interface; pushed: " + skills.pushed()
                + "\nrunner: " + runner.lines() + "\n" + runner.stderr());
    }

    @Test
    public void followsTheCachedDecisionThenTheNextAndPushesSkillsWithTheirPorts() throws Exception {
        start(100);
        decide("pick"); // before the runner starts: the broker's cache hands it over
        runner = runner();
        JsonNode started = runner.await("start", l -> l.path("event").asText().equals("start"), 30_000);
        assertTrue(started.toString(), started.path("decisions").asBoolean());
        assertEquals(List.of("MoveTo", "objectdrop", "objectpick"),
                Json.MAPPER.convertValue(started.path("skills"), List.class));
        awaitPushed("MoveTo to the pick place", moveTo(-2.5, 6.4));
        awaitPushed("objectpick 0", s -> s.path("name").asText().equals("objectpick")
                && s.path("in-attribute").path("obj_index").asInt(-9) == 0);
        awaitPushed("objectdrop -1", s -> s.path("name").asText().equals("objectdrop")
                && s.path("in-attribute").path("obj_index").asInt(9) == -1);
        decide("dock");
        awaitPushed("MoveTo to the charger", moveTo(-9.33, 2.17));
        JsonNode stopped = runner.stop();
        assertEquals(stopped.toString(), 0, stopped.path("counters").path("rejectedDecisions").asInt());
    }

    @Test
    public void survivesMalformedBusMessagesAndABrokerRestart() throws Exception {
        start(100);
        decide("deliver");
        runner = runner();
        awaitPushed("MoveTo to the drop place", moveTo(-8.08, 4.11));
        engine.publish("miron.variant.task", "{not json");
        engine.publish("miron.variant.task", "{\"varpoint\":\"other\",\"value\":\"dock\"}");
        engine.publish("miron.variant.task", "{\"varpoint\":\"task\"}");
        engine.publish("miron.blackboard.maxVelocity", "{\"varpoint\":\"maxVelocity\",\"value\":\"fast\"}");
        engine.publish("miron.variant.task", "{\"varpoint\":\"task\",\"value\":\"pick\"} trailing");
        engine.publish("miron.variant.task", "{\"varpoint\":\"task\",\"value\":\"pick\",\"seq\":99}");
        awaitPushed("MoveTo to the pick place after the malformed messages", moveTo(-2.5, 6.4));
        assertTrue(runner.isAlive());

        broker.close();
        broker = new Broker(endpoints).start(); // same endpoints, empty cache
        assertTrue(engine.awaitReady(10_000));
        int before = skills.pushed().size();
        decide("dock");
        awaitPushed("MoveTo to the charger through the restarted broker", moveTo(-9.33, 2.17));
        assertTrue(skills.pushed().size() > before);
        JsonNode stopped = runner.stop();
        assertEquals(stopped.toString(), 5, stopped.path("counters").path("rejectedDecisions").asInt());
    }

    @Test
    public void aHaltedSkillIsAbortedOnTheSkillInterface() throws Exception {
        start(60_000); // MoveTo would run a minute
        decide("pick");
        runner = runner();
        awaitPushed("MoveTo to the pick place", moveTo(-2.5, 6.4));
        decide("dock"); // the Switch leaves the pick branch: its running MoveTo is halted
        awaitPushed("MoveTo to the charger", moveTo(-9.33, 2.17));
        awaitResults("the pick MoveTo ends with ABORT", 1);
        JsonNode stopped = runner.stop(); // SIGTERM halts the tree: the charger MoveTo is aborted too
        awaitResults("the charger MoveTo ends with ABORT", 2);
        assertEquals(stopped.toString(), 2, stopped.path("counters").path("aborted").asInt());
    }

    /** miron.blackboard.<vp> numbers reach the blackboard under the varpoint's name, where the woven ports read them. */
    @Test
    public void blackboardDecisionsReachTheSkillsPorts() throws Exception {
        start(100);
        engine.publishRetained("driveSpeed", "miron.blackboard.driveSpeed", "{\"varpoint\":\"driveSpeed\",\"value\":0.7,\"seq\":1,\"time\":1}");
        engine.publishRetained("inflation", "miron.blackboard.inflation", "{\"varpoint\":\"inflation\",\"value\":0.4,\"seq\":1,\"time\":1}");
        for (String[] vp : new String[][] { { "navigation", "normal" }, { "preparation", "none" }, { "courtesy", "silent" } }) {
            engine.publishRetained(vp[0], "miron.variant." + vp[0],
                    "{\"varpoint\":\"" + vp[0] + "\",\"value\":\"" + vp[1] + "\",\"seq\":1,\"time\":1}");
        }
        runner = new BtcppRunner(List.of(hospital.toString(), "--bus", endpoints.busOut(), "--skill-requests",
                endpoints.request(), "--skill-results", endpoints.skillEvents(), "--period", "20"));
        JsonNode drive = awaitPushed("MoveBase with the decided speed and inflation", s -> s.path("name").asText().equals("MoveBase")
                && s.path("in-attribute").path("max_speed").asDouble() == 0.7);
        assertEquals(drive.toString(), 0.4, drive.path("in-attribute").path("inflation").asDouble(), 0);
        assertEquals(drive.toString(), "cardiology", drive.path("in-attribute").path("goal").asText());
        assertTrue("the preparation 'none' skips charging: " + skills.pushed(),
                skills.pushed().stream().noneMatch(s -> s.path("name").asText().equals("Charge")));
    }

    /**
     * A port P with P + 1 free too: BehaviorTree.CPP's Groot2 publisher binds both (requests on P,
     * its publisher on P + 1), and fails to start if the second is taken.
     */
    private static int freePortPair() throws java.io.IOException {
        java.net.InetAddress lo = java.net.InetAddress.getLoopbackAddress();
        for (int i = 0; i < 50; i++) {
            // below the ephemeral range, as every port of these tests (FreePorts)
            try (java.net.ServerSocket a = new java.net.ServerSocket(org.miron.runtime.FreePorts.take(1)[0], 1, lo);
                    java.net.ServerSocket b = new java.net.ServerSocket(a.getLocalPort() + 1, 1, lo)) {
                return a.getLocalPort();
            } catch (java.net.BindException taken) {
                // P + 1 is in use: try another P
            }
        }
        throw new java.io.IOException("no two consecutive free ports on the loopback");
    }

    @Test
    public void grootAttachesBehaviorTreeCppsPublisher() throws Exception {
        start(100);
        int port = freePortPair();
        runner = new BtcppRunner(List.of(tree.toString(), "--bus", endpoints.busOut(), "--skill-requests",
                endpoints.request(), "--skill-results", endpoints.skillEvents(), "--decision-wait", "0",
                "--groot", Integer.toString(port)));
        JsonNode started = runner.await("start", l -> l.path("event").asText().equals("start"), 30_000);
        assertEquals(port, started.path("groot").asInt());
        // Groot2 connects a ZeroMQ REQ to PORT: the publisher answers there once the tree runs. A
        // request sent while its server thread starts may go unanswered: ask again on a new socket.
        String xml = "";
        try (org.zeromq.ZContext ctx = new org.zeromq.ZContext()) {
            for (int attempt = 0; attempt < 12 && !xml.contains("VariantAction"); attempt++) {
                org.zeromq.ZMQ.Socket req = ctx.createSocket(org.zeromq.SocketType.REQ);
                req.setLinger(0);
                req.setReceiveTimeOut(5_000);
                req.connect("tcp://127.0.0.1:" + port);
                // Groot2's request header: protocol 2, request type 'T' (the full tree), a unique id
                byte[] header = { 2, 'T', 0, 0, 0, (byte) (attempt + 1) };
                assertTrue(req.send(header));
                byte[] reply = req.recv();
                if (reply != null && req.hasReceiveMore()) {
                    xml = new String(req.recv(), java.nio.charset.StandardCharsets.UTF_8);
                }
                ctx.destroySocket(req);
            }
        }
        assertTrue("the Groot2 publisher sends the tree: " + xml + "\n" + runner.stderr(), xml.contains("VariantAction"));
    }

    private void awaitResults(String what, int aborts) throws InterruptedException {
        long end = System.currentTimeMillis() + 20_000;
        while (System.currentTimeMillis() < end) {
            long n = skills.results().stream().filter(r -> r.path("result").path("result").asText().equals("ABORT")).count();
            if (n >= aborts) {
                return;
            }
            Thread.sleep(20);
        }
        throw new AssertionError(what + ": results " + skills.results() + "\nrunner: " + runner.lines() + "\n" + runner.stderr());
    }
}
