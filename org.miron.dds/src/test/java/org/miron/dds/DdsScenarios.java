package org.miron.dds;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.miron.dds.config.BridgeConfig;
import org.miron.dds.config.ConfigReader;
import org.miron.dds.transport.IhmcTransport;
import org.miron.runtime.Endpoints;
import org.miron.runtime.broker.Broker;
import org.miron.runtime.bus.BusClient;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.roqme.LiveProvider;
import org.miron.runtime.roqme.expr.CompiledModel;
import org.miron.runtime.roqme.expr.Compiler;
import org.miron.runtime.roqme.model.ModelReader;
import org.miron.testkit.RepositoryRoot;
import org.miron.testkit.runtime.BusProbe;
import org.miron.testkit.runtime.EngineFixture;
import org.miron.testkit.runtime.TestModels;

/**
 * The bridge against an independent DDS implementation (Cyclone DDS, dds_peer.py) with the real
 * broker, engine and RoQME provider. Each public method is one scenario, run by {@link NetnsMain}
 * in a private network namespace (DdsBridgeTest); every wait is on an event (a match, a sample, a
 * bus message), none on time alone.
 */
public final class DdsScenarios {
    static final long TIMEOUT = 60_000;
    private static final String LOOP_CONFIG = """
            {"domain": 0,
             "contexts": [{"topic": "battery_state", "type": "sensor_msgs/BatteryState", "field": "percentage",
                           "scale": 100, "context": "BatteryLevel", "namespace": "Intralogistics"}],
             "decisions": [{"varpoint": "task", "topic": "miron/task"},
                           {"varpoint": "maxVelocity", "topic": "miron/max_velocity", "type": "std_msgs/Float64"}],
             "estimates": [{"metric": "power_autonomy", "namespace": "Intralogistics", "topic": "miron/power_autonomy"}]}
            """;

    static Bridge bridge(String config, Endpoints ep) throws Exception {
        BridgeConfig c = ConfigReader.read(config, IhmcTransport.CATALOG);
        Bridge b = new Bridge(c, new IhmcTransport(c.domain(), c.name(), c.interfaces()), ep.busIn(), ep.busOut(), 500).start();
        assertTrue("the bridge reaches the broker", b.awaitReady(TIMEOUT));
        return b;
    }

    /** A bridge whose configuration is the file {@code config} (its message packages relative to it), answering change-parameter on ep.skill(). */
    static Bridge bridge(Path config, Endpoints ep) throws Exception {
        BridgeConfig c = ConfigReader.read(Files.readString(config), config, IhmcTransport.CATALOG, System.err::println);
        Bridge b = new Bridge(c, new IhmcTransport(c.domain(), c.name(), c.interfaces(), c.types()), ep.busIn(), ep.busOut(),
                ep.skill(), 500).start();
        assertTrue("the bridge reaches the broker", b.awaitReady(TIMEOUT));
        return b;
    }

    /** Waits until the bridge's own endpoints on the topic have matched the peer (matching is seen on each side at its own time). */
    static void awaitMatched(Bridge b, String ddsTopic) throws InterruptedException {
        long end = System.currentTimeMillis() + TIMEOUT;
        while (b.matched(ddsTopic) < 1) {
            if (System.currentTimeMillis() > end) {
                throw new AssertionError("the bridge never matched the peer on " + ddsTopic);
            }
            Thread.sleep(20);
        }
    }

    private static LiveProvider provider(Endpoints ep) throws Exception {
        CompiledModel m = Compiler.compile(ModelReader.parse("intralogistics.roqme.json", TestModels.roqme("intralogistics.roqme.json")),
                new HashMap<>());
        LiveProvider p = new LiveProvider(m, 100, 5000, ep.busIn(), ep.busOut()).start();
        assertTrue(p.awaitSubscribed(TIMEOUT));
        return p;
    }

    /**
     * The loop: a BatteryState from the robot moves the provider's power_autonomy, the engine
     * decides task = dock, the robot receives it on miron/task; a node that starts afterwards gets
     * the current decision (transient-local).
     */
    public void batteryMovesTheMetricAndTheDecision(Path dir) throws Exception {
        try (EngineFixture f = new EngineFixture(dir); BusProbe roqme = new BusProbe(f.endpoints.busOut(), "roqme.")) {
            f.startAll(); // testbot: task = dock when power_autonomy < 0.3; BatteryLevel is 50 now
            try (LiveProvider p = provider(f.endpoints); Bridge b = bridge(LOOP_CONFIG, f.endpoints);
                    CyclonePeer robot = new CyclonePeer(dir)) {
                robot.endpoint("reader", "task", "rt/miron/task", "std_msgs/String", ",\"durability\":\"transient_local\",\"depth\":1");
                robot.endpoint("writer", "battery", "rt/battery_state", "sensor_msgs/BatteryState", "");
                robot.awaitMatched("task");
                assertNotNull("the current decision reaches the robot",
                        robot.awaitSample("task", d -> d.path("data").asText().equals("pickDeliverCharge")));
                robot.awaitMatched("battery");
                awaitMatched(b, "rt/battery_state");
                robot.write("battery", "{\"header\":{\"frame_id\":\"base\"},\"percentage\":0.2,\"cell_voltage\":[3.6,3.7]}");
                JsonNode ctx = roqme.await(Topics.CONTEXT, c -> c.path("name").asText().equals("BatteryLevel")
                        && c.path("value").asDouble() < 21, TIMEOUT);
                assertNotNull("roqme.context BatteryLevel from the robot's battery_state", ctx);
                assertEquals(20.0, ctx.path("value").asDouble(), 1e-9);
                assertEquals("number", ctx.path("type").asText());
                assertEquals("Intralogistics", ctx.path("namespace").asText());
                assertNotNull("the provider's power_autonomy falls", roqme.await(Topics.ESTIMATE,
                        e -> e.path("name").asText().equals("power_autonomy") && e.path("value").asDouble() < 0.3, TIMEOUT));
                assertNotNull("the engine decides dock", f.awaitVariant("task", "dock"));
                assertNotNull("the robot receives dock", robot.awaitSample("task", d -> d.path("data").asText().equals("dock")));
                // a node that starts late (a Nav2 selector) gets the current value at once
                try (CyclonePeer late = new CyclonePeer(dir)) {
                    late.endpoint("reader", "task", "rt/miron/task", "std_msgs/String", ",\"durability\":\"transient_local\",\"depth\":1");
                    JsonNode first = late.awaitSample("task", d -> true);
                    assertNotNull("the late node gets the current decision", first);
                    assertEquals("dock", first.path("data").asText());
                    // a numeric varpoint as std_msgs/Float64, the metric as std_msgs/Float64
                    late.endpoint("reader", "vel", "rt/miron/max_velocity", "std_msgs/Float64", ",\"durability\":\"transient_local\",\"depth\":1");
                    late.endpoint("reader", "pa", "rt/miron/power_autonomy", "std_msgs/Float64", ",\"durability\":\"transient_local\",\"depth\":1");
                    JsonNode vel = late.awaitSample("vel", d -> true);
                    assertNotNull("maxVelocity reaches the late node", vel);
                    List<BusProbe.Message> decisions = f.probe.messages(Topics.DECISION);
                    JsonNode decided = decisions.get(decisions.size() - 1).body(); // the current decision
                    assertEquals(decided.path("decisions").path("maxVelocity").asDouble(), vel.path("data").asDouble(), 0);
                    JsonNode pa = late.awaitSample("pa", d -> true);
                    assertNotNull("power_autonomy reaches the late node", pa);
                    assertTrue(pa.toString(), pa.path("data").asDouble() >= 0 && pa.path("data").asDouble() <= 1);
                }
                assertEquals(0, b.count("malformedInput"));
            }
        }
    }

    /**
     * RoQME's own topics, keyed by name as the original IDL declares them (the peer's structs carry
     * {@code @key name}): a RoqmeDoubleContext and a RoqmeEnumContext in, every roqme.estimate out
     * as RoqmeEstimate; then RoqmeEstimate in.
     */
    public void roqmeTypesBothWays(Path dir) throws Exception {
        Endpoints ep = Endpoints.freeLoopback();
        try (Broker broker = new Broker(ep).start(); BusProbe probe = new BusProbe(ep.busOut(), "roqme.");
                BusClient input = new BusClient("test-input", ep.busIn(), null, List.of(), (t, x) -> { }).start();
                CyclonePeer tools = new CyclonePeer(dir)) {
            assertTrue(input.awaitReady(TIMEOUT));
            String partition = ",\"partition\":\"Roqme DDS partition\"";
            try (Bridge out = bridge("{\"roqme\": {\"namespace\": \"Intralogistics\", \"estimates\": \"out\"}}", ep)) {
                tools.endpoint("writer", "ctx", "RoqmeDoubleContext", "RoqmeDoubleContext", partition);
                tools.endpoint("writer", "enum", "RoqmeEnumContext", "RoqmeEnumContext", partition);
                tools.endpoint("reader", "est", "RoqmeEstimate", "RoqmeEstimate", partition);
                tools.awaitMatched("ctx");
                awaitMatched(out, "RoqmeDoubleContext");
                tools.write("ctx", "{\"name\":\"BatteryLevel\",\"value\":[42.5]}");
                JsonNode c = probe.await(Topics.CONTEXT, x -> x.path("name").asText().equals("BatteryLevel"), TIMEOUT);
                assertNotNull("RoqmeDoubleContext -> roqme.context", c);
                assertEquals(42.5, c.path("value").asDouble(), 0);
                assertEquals("number", c.path("type").asText());
                assertEquals("Intralogistics", c.path("namespace").asText());
                tools.awaitMatched("enum");
                awaitMatched(out, "RoqmeEnumContext");
                tools.write("enum", "{\"name\":\"FreeSpace\",\"value\":[\"HIGH\"]}");
                JsonNode e = probe.await(Topics.CONTEXT, x -> x.path("name").asText().equals("FreeSpace"), TIMEOUT);
                assertNotNull("RoqmeEnumContext -> roqme.context", e);
                assertEquals("enum", e.path("type").asText());
                assertEquals("HIGH", e.path("value").asText());
                tools.write("ctx", "{\"name\":\"BatteryLevel\",\"value\":[]}"); // no value: dropped
                tools.awaitMatched("est");
                awaitMatched(out, "RoqmeEstimate");
                input.publish(Topics.ESTIMATE, "{\"name\":\"power_autonomy\",\"namespace\":\"Intralogistics\",\"value\":0.25,\"time\":1}");
                JsonNode est = tools.awaitSample("est", x -> x.path("name").asText().equals("power_autonomy"));
                assertNotNull("roqme.estimate -> RoqmeEstimate", est);
                assertEquals(0.25, est.path("value").asDouble(), 0);
                long end = System.currentTimeMillis() + TIMEOUT;
                while (out.count("malformedInput") < 1 && System.currentTimeMillis() < end) {
                    Thread.sleep(20);
                }
                assertEquals("the empty context is counted and dropped", 1, out.count("malformedInput"));
                assertEquals(2, out.count("contextsIn"));
            }
            try (Bridge in = bridge("{\"roqme\": {\"namespace\": \"Intralogistics\", \"contexts\": false, \"estimates\": \"in\"}}", ep)) {
                tools.endpoint("writer", "estw", "RoqmeEstimate", "RoqmeEstimate", partition);
                tools.awaitMatched("estw");
                awaitMatched(in, "RoqmeEstimate");
                tools.write("estw", "{\"name\":\"safety\",\"value\":0.75}");
                JsonNode s = probe.await(Topics.ESTIMATE, x -> x.path("name").asText().equals("safety"), TIMEOUT);
                assertNotNull("RoqmeEstimate -> roqme.estimate (the original provider feeding our engine)", s);
                assertEquals(0.75, s.path("value").asDouble(), 0);
                assertEquals("Intralogistics", s.path("namespace").asText());
                tools.write("estw", "{\"name\":\"safety\",\"value\":7.5}"); // outside [0, 1]: dropped
                long end = System.currentTimeMillis() + TIMEOUT;
                while (in.count("malformedInput") < 1 && System.currentTimeMillis() < end) {
                    Thread.sleep(20);
                }
                assertEquals(1, in.count("malformedInput"));
                // a disposed instance carries no estimate: neither passed on nor counted as malformed
                tools.send("{\"op\":\"dispose\",\"id\":\"estw\",\"data\":{\"name\":\"safety\"}}");
                tools.write("estw", "{\"name\":\"mission\",\"value\":0.5}");
                assertNotNull(probe.await(Topics.ESTIMATE, x -> x.path("name").asText().equals("mission"), TIMEOUT));
                assertEquals(1, in.count("malformedInput"));
                assertEquals("safety 0.75 only", 1, probe.messages(Topics.ESTIMATE).stream()
                        .filter(m -> m.body().path("name").asText().equals("safety")).count());
            }
        }
    }

    /**
     * The documented example: examples/intralogistics/dds/robot.py (Cyclone, its own network
     * defaults) stands in for the robot beside the example's bridge configuration; its battery
     * drains until the engine decides dock, which it prints and exits on; maxVelocity reaches it as a
     * std_msgs/Float64 and as a nav2_msgs/SpeedLimit, the latter through change-parameter answered by
     * the bridge (no skill interface runs).
     */
    public void exampleRobotClosesTheLoop(Path dir) throws Exception {
        Path example = RepositoryRoot.resolve("examples/intralogistics/dds");
        try (EngineFixture f = new EngineFixture(dir); BusProbe contexts = new BusProbe(f.endpoints.busOut(), Topics.CONTEXT)) {
            f.startInfrastructure(); // no skill interface: the bridge answers the engine's change-parameter (transvel)
            try (LiveProvider p = provider(f.endpoints); Bridge b = bridge(example.resolve("bridge.json"), f.endpoints)) {
                f.startEngine(f.options());
                assertNotNull("the initial decision", f.awaitVariant("task", "pickDeliverCharge"));
                ProcessBuilder pb = new ProcessBuilder(System.getProperty("dds.python", "python3"), "-u",
                        example.resolve("robot.py").toString(), "--until", "dock", "--timeout", "240", "--period", "0.5", "--step", "0.05")
                        .redirectErrorStream(true);
                pb.environment().remove("CYCLONEDDS_URI");
                Process robot = pb.start();
                String out;
                try {
                    out = new String(robot.getInputStream().readAllBytes(), StandardCharsets.UTF_8); // until it exits
                    assertTrue("the robot exits", robot.waitFor(30, TimeUnit.SECONDS));
                } finally {
                    robot.destroyForcibly();
                }
                assertEquals("robot.py:\n" + out, 0, robot.exitValue());
                List<String> tasks = out.lines().filter(l -> l.startsWith("task: ")).toList();
                // the current decision at once (transient-local), well before the battery (-0.05 per 0.5 s) runs low
                assertEquals(out, "task: pickDeliverCharge", tasks.get(0));
                assertEquals(out, "task: dock", tasks.get(tasks.size() - 1));
                assertTrue(out, out.lines().anyMatch(l -> l.startsWith("maxVelocity: ")));
                assertTrue(out, out.lines().anyMatch(l -> l.matches("speed_limit: [0-9.]+ m/s")));
                awaitAcked(f);
                assertNotNull("its battery reached the bus as BatteryLevel", contexts.await(Topics.CONTEXT,
                        c -> c.path("name").asText().equals("BatteryLevel") && c.path("value").asDouble() < 30, TIMEOUT));
                assertEquals(0, b.count("malformedInput"));
            }
        }
    }

    /**
     * A robot with only its own message types (my_robot_msgs/PowerStatus in, nav2_msgs/SpeedLimit
     * out, both declared by the peer from their field lists): its draining battery brings the
     * engine to dock; maxVelocity, an arch-bound parameter, reaches it as a SpeedLimit of decision ×
     * 0.01 through the engine's change-parameter query, which the bridge answers in the skill
     * interface's place (no skill interface runs); a robot that joins late gets both at once.
     */
    public void robotWithItsOwnTypesClosesTheLoop(Path dir) throws Exception {
        Path msgs = Path.of(DdsScenarios.class.getResource("msgs/my_robot_msgs/package.xml").toURI()).getParent();
        Path config = dir.resolve("bridge.json");
        Files.writeString(config, """
                {"messages": ["%s", "%s"],
                 "contexts": [{"topic": "power_status", "type": "my_robot_msgs/PowerStatus", "field": "charge_percent",
                               "context": "BatteryLevel", "namespace": "Intralogistics"}],
                 "decisions": [{"varpoint": "task", "topic": "miron/task"},
                               {"varpoint": "maxVelocity", "topic": "speed_limit", "type": "nav2_msgs/SpeedLimit", "field": "speed_limit",
                                "scale": 0.01, "set": {"percentage": false, "header.frame_id": "map"}, "parameter": "transvel"}]}
                """.formatted(dir.relativize(msgs), dir.relativize(RepositoryRoot.resolve("examples/nav2/msgs/nav2_msgs"))));
        String latched = ",\"durability\":\"transient_local\",\"depth\":1";
        try (EngineFixture f = new EngineFixture(dir); BusProbe roqme = new BusProbe(f.endpoints.busOut(), "roqme.")) {
            f.startInfrastructure(); // no skill interface: the bridge answers change-parameter
            try (LiveProvider p = provider(f.endpoints); Bridge b = bridge(config, f.endpoints); CyclonePeer robot = new CyclonePeer(dir)) {
                f.startEngine(f.options());
                assertNotNull("the initial decision", f.awaitVariant("task", "pickDeliverCharge"));
                robot.endpoint("reader", "task", "rt/miron/task", "std_msgs/String", latched);
                robot.endpoint("reader", "speed", "rt/speed_limit", "nav2_msgs/SpeedLimit", latched);
                robot.endpoint("writer", "power", "rt/power_status", "my_robot_msgs/PowerStatus", "");
                robot.awaitMatched("speed");
                JsonNode limit = robot.awaitSample("speed", d -> true);
                assertNotNull("the robot receives a SpeedLimit", limit);
                assertSpeedLimit(f, limit);
                awaitAcked(f);
                assertTrue(b.count("parametersIn") >= 1);
                robot.awaitMatched("power");
                awaitMatched(b, "rt/power_status");
                for (double level : new double[] {80, 50, 20}) { // the battery drains
                    robot.write("power", "{\"header\":{\"frame_id\":\"base\"},\"charge_percent\":" + level
                            + ",\"status\":1,\"charger\":{\"dock_id\":\"d1\"},\"cell_voltages\":[3.5,3.6]}");
                    assertNotNull("BatteryLevel " + level + " from the robot's PowerStatus", roqme.await(Topics.CONTEXT,
                            c -> c.path("name").asText().equals("BatteryLevel") && c.path("value").asDouble() == level, TIMEOUT));
                }
                assertNotNull("the engine decides dock", f.awaitVariant("task", "dock"));
                assertNotNull("the robot receives dock", robot.awaitSample("task", d -> d.path("data").asText().equals("dock")));
                try (CyclonePeer late = new CyclonePeer(dir)) {
                    late.endpoint("reader", "task", "rt/miron/task", "std_msgs/String", latched);
                    late.endpoint("reader", "speed", "rt/speed_limit", "nav2_msgs/SpeedLimit", latched);
                    JsonNode task = late.awaitSample("task", d -> true);
                    assertNotNull("the late robot gets the current task", task);
                    assertEquals("dock", task.path("data").asText());
                    JsonNode lateLimit = late.awaitSample("speed", d -> true);
                    assertNotNull("the late robot gets the current speed limit", lateLimit);
                    assertSpeedLimit(f, lateLimit);
                }
                assertEquals(0, b.count("malformedInput"));
                assertEquals(0, b.count("queriesIgnored"));
                // a robot whose PowerStatus is another type of the same name: its samples do not decode, are counted and dropped
                try (CyclonePeer other = new CyclonePeer(dir)) {
                    other.endpoint("writer", "power", "rt/power_status", "truncated my_robot_msgs/PowerStatus", "");
                    other.awaitMatched("power");
                    long contexts = b.count("contextsIn");
                    // Written again until one arrives: "matched" on the writer's side does not mean
                    // the bridge's reader has matched it back yet, and a sample before that is lost.
                    long end = System.currentTimeMillis() + TIMEOUT;
                    long nextWrite = 0;
                    while (b.count("malformedInput") < 1 && System.currentTimeMillis() < end) {
                        if (System.currentTimeMillis() >= nextWrite) {
                            other.write("power", "{\"header\":{\"frame_id\":\"x\"}}");
                            nextWrite = System.currentTimeMillis() + 1000;
                        }
                        Thread.sleep(20);
                    }
                    assertTrue("the undecodable PowerStatus is counted", b.count("malformedInput") >= 1);
                    assertEquals("and dropped", contexts, b.count("contextsIn"));
                }
            }
        }
    }

    /** Waits until the engine counts a change-parameter acknowledged (by the bridge: no skill interface runs). */
    private static void awaitAcked(EngineFixture f) throws InterruptedException {
        long end = System.currentTimeMillis() + TIMEOUT;
        while (f.engine.status().get("paramAcked") < 1 && System.currentTimeMillis() < end) {
            Thread.sleep(20);
        }
        assertTrue("the engine's change-parameter is acknowledged by the bridge", f.engine.status().get("paramAcked") >= 1);
    }

    /** speed_limit = the current maxVelocity decision × 0.01, the set fields, the header stamped. */
    private static void assertSpeedLimit(EngineFixture f, JsonNode limit) {
        List<BusProbe.Message> decisions = f.probe.messages(Topics.DECISION);
        double decided = decisions.get(decisions.size() - 1).body().path("decisions").path("maxVelocity").asDouble();
        assertEquals(limit.toString(), decided * 0.01, limit.path("speed_limit").asDouble(), 1e-12);
        assertEquals(limit.toString(), false, limit.path("percentage").asBoolean());
        assertEquals(limit.toString(), "map", limit.path("header").path("frame_id").asText());
        assertTrue(limit.toString(), limit.path("header").path("stamp").path("sec").asLong() > 1_600_000_000L);
    }

    /** The native key switch on a real participant refuses what it does not recognise (KeySwitchChecks). */
    public void keySwitchRefusesWhatItDoesNotRecognise(Path dir) throws Exception {
        org.miron.dds.transport.KeySwitchChecks.run();
    }

    /**
     * {@code "keyed": false}: peers that declared RoQME's structs without the key (a keyed and an
     * unkeyed topic never match) still reach the bus, both ways.
     */
    public void unkeyedRoqmeTopicsWhenConfigured(Path dir) throws Exception {
        Endpoints ep = Endpoints.freeLoopback();
        String partition = ",\"partition\":\"Roqme DDS partition\"";
        try (Broker broker = new Broker(ep).start(); BusProbe probe = new BusProbe(ep.busOut(), "roqme.");
                BusClient input = new BusClient("test-input", ep.busIn(), null, List.of(), (t, x) -> { }).start();
                CyclonePeer tools = new CyclonePeer(dir);
                Bridge b = bridge("{\"roqme\": {\"keyed\": false, \"contexts\": [\"RoqmeDoubleContext\"], \"estimates\": \"out\"}}", ep)) {
            assertTrue(input.awaitReady(TIMEOUT));
            tools.endpoint("writer", "ctx", "RoqmeDoubleContext", "unkeyed RoqmeDoubleContext", partition);
            tools.endpoint("reader", "est", "RoqmeEstimate", "unkeyed RoqmeEstimate", partition);
            tools.awaitMatched("ctx");
            awaitMatched(b, "RoqmeDoubleContext");
            tools.write("ctx", "{\"name\":\"HumanDistance\",\"value\":[1.25]}");
            JsonNode c = probe.await(Topics.CONTEXT, x -> x.path("name").asText().equals("HumanDistance"), TIMEOUT);
            assertNotNull("unkeyed RoqmeDoubleContext -> roqme.context", c);
            assertEquals(1.25, c.path("value").asDouble(), 0);
            tools.awaitMatched("est");
            awaitMatched(b, "RoqmeEstimate");
            input.publish(Topics.ESTIMATE, "{\"name\":\"safety\",\"namespace\":\"\",\"value\":0.5,\"time\":1}");
            JsonNode est = tools.awaitSample("est", x -> x.path("name").asText().equals("safety"));
            assertNotNull("roqme.estimate -> unkeyed RoqmeEstimate", est);
            assertEquals(0.5, est.path("value").asDouble(), 0);
        }
    }

    /** Samples whose field is missing, NaN or of the wrong type are counted and dropped; the bridge goes on. */
    public void malformedFieldsAreCountedAndDropped(Path dir) throws Exception {
        Endpoints ep = Endpoints.freeLoopback();
        String config = """
                {"contexts": [
                  {"topic": "battery_state", "type": "sensor_msgs/BatteryState", "field": "percentage", "scale": 100,
                   "context": "BatteryLevel", "namespace": "Intralogistics"},
                  {"topic": "battery_state", "type": "sensor_msgs/BatteryState", "field": "cell_voltage[1]",
                   "context": "CellVoltage"},
                  {"topic": "distance", "type": "std_msgs/String", "field": "data", "as": "number", "context": "HumanDistance"}]}
                """;
        try (Broker broker = new Broker(ep).start(); BusProbe probe = new BusProbe(ep.busOut(), "roqme.");
                Bridge b = bridge(config, ep); CyclonePeer robot = new CyclonePeer(dir)) {
            robot.endpoint("writer", "battery", "rt/battery_state", "sensor_msgs/BatteryState", "");
            robot.endpoint("writer", "distance", "rt/distance", "std_msgs/String", "");
            robot.awaitMatched("battery");
            robot.awaitMatched("distance");
            awaitMatched(b, "rt/battery_state");
            awaitMatched(b, "rt/distance");
            robot.write("battery", "{\"percentage\":NaN,\"cell_voltage\":[3.6]}"); // NaN; and no second cell
            robot.write("distance", "{\"data\":\"far away\"}"); // not a number
            robot.write("distance", "{\"data\":\"1.5\"}"); // a number in a string: fine
            robot.write("battery", "{\"percentage\":0.5,\"cell_voltage\":[3.6,3.7]}");
            assertNotNull(probe.await(Topics.CONTEXT, x -> x.path("name").asText().equals("HumanDistance")
                    && x.path("value").asDouble() == 1.5, TIMEOUT));
            assertNotNull(probe.await(Topics.CONTEXT, x -> x.path("name").asText().equals("BatteryLevel")
                    && x.path("value").asDouble() == 50, TIMEOUT));
            assertNotNull(probe.await(Topics.CONTEXT, x -> x.path("name").asText().equals("CellVoltage")
                    && Math.abs(x.path("value").asDouble() - 3.7) < 1e-6, TIMEOUT));
            assertEquals("NaN percentage, missing cell, text distance", 3, b.count("malformedInput"));
            assertEquals(3, b.count("contextsIn"));
            assertTrue(probe.messages(Topics.CONTEXT).stream().noneMatch(m -> m.body().path("value").asText().contains("NaN")));
        }
    }

    /**
     * The bridge restarts while the decision changes: the new bridge writes the current decision
     * from the broker's cache; a robot that crashes and comes back is matched again both ways.
     */
    public void restartLosesNoDecisionAndAPeerComesBack(Path dir) throws Exception {
        try (EngineFixture f = new EngineFixture(dir); BusProbe contexts = new BusProbe(f.endpoints.busOut(), Topics.CONTEXT)) {
            f.startAll();
            String config = LOOP_CONFIG;
            CyclonePeer robot = new CyclonePeer(dir);
            try {
                robot.endpoint("reader", "task", "rt/miron/task", "std_msgs/String", ",\"durability\":\"transient_local\",\"depth\":1");
                try (Bridge first = bridge(config, f.endpoints)) {
                    robot.awaitMatched("task");
                    assertNotNull(robot.awaitSample("task", d -> d.path("data").asText().equals("pickDeliverCharge")));
                }
                f.estimate("power_autonomy", 0.1); // decided while no bridge runs
                assertNotNull(f.awaitVariant("task", "dock"));
                try (Bridge second = bridge(config, f.endpoints)) {
                    assertNotNull("the restarted bridge sends the decision taken meanwhile",
                            robot.awaitSample("task", d -> d.path("data").asText().equals("dock")));
                    robot.kill(); // the robot crashes ...
                    robot = new CyclonePeer(dir); // ... and comes back
                    robot.endpoint("reader", "task", "rt/miron/task", "std_msgs/String", ",\"durability\":\"transient_local\",\"depth\":1");
                    robot.endpoint("writer", "battery", "rt/battery_state", "sensor_msgs/BatteryState", "");
                    assertNotNull("matched again: the current decision", robot.awaitSample("task", d -> d.path("data").asText().equals("dock")));
                    robot.awaitMatched("battery");
                    awaitMatched(second, "rt/battery_state");
                    robot.write("battery", "{\"percentage\":0.33}");
                    assertNotNull("matched again: its contexts reach the bus", contexts.await(Topics.CONTEXT,
                            x -> Math.abs(x.path("value").asDouble() - 33) < 1e-6, TIMEOUT));
                }
            } finally {
                robot.close();
            }
        }
    }
}
