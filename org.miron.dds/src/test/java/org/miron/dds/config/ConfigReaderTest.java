package org.miron.dds.config;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.Test;
import org.miron.dds.config.BridgeConfig.ContextType;
import org.miron.dds.transport.IhmcTransport;
import org.miron.dds.transport.Qos;
import org.miron.testkit.JsonSchemaFile;
import org.miron.testkit.RepositoryRoot;

/** The bridge's configuration: what it accepts, and start-up errors with their positions (no DDS needed). */
public class ConfigReaderTest {
    private static final String ISSUE_SHAPE = """
            {"domain": 0,
             "contexts": [{"topic": "battery_state", "type": "sensor_msgs/BatteryState", "field": "percentage",
                           "scale": 100, "context": "BatteryLevel", "namespace": "Intralogistics"}],
             "decisions": [{"varpoint": "task", "topic": "miron/task"}]}
            """;

    private static BridgeConfig read(String json) throws ConfigException {
        return ConfigReader.read(json, IhmcTransport.CATALOG);
    }

    private static String error(String json) {
        try {
            read(json);
        } catch (ConfigException e) {
            return e.format("bridge.json");
        }
        fail("accepted: " + json);
        return null;
    }

    @Test
    public void theIssuesShapeWithItsDefaults() throws Exception {
        BridgeConfig c = read(ISSUE_SHAPE);
        assertEquals(0, c.domain());
        assertEquals("loopback only by default", List.of("127.0.0.1"), c.interfaces().stream().map(a -> a.getHostAddress()).toList());
        BridgeConfig.ContextMapping m = c.contexts().get(0);
        assertEquals(ContextType.NUMBER, m.as());
        assertEquals(100, m.scale(), 0);
        assertEquals(List.of("percentage"), m.path());
        assertEquals("a reader that matches best-effort sensors too", new Qos(false, false, 10), m.qos());
        assertEquals("std_msgs/String", c.decisions().get(0).type());
        assertEquals("what Nav2's selectors expect", Qos.LATCHED, c.decisions().get(0).qos());
        assertEquals(null, c.roqme());
        assertTrue(JsonSchemaFile.DDS_BRIDGE.problems(ISSUE_SHAPE).isEmpty());
    }

    @Test
    public void nestedPathsInterfacesQosAndRoqme() throws Exception {
        BridgeConfig c = read("""
                {"domain": 7, "interfaces": ["192.168.1.20"],
                 "contexts": [{"topic": "/battery_state", "type": "sensor_msgs/BatteryState", "field": "header.stamp.sec", "context": "Stamp"},
                              {"topic": "battery_state", "type": "sensor_msgs/BatteryState", "field": "cell_voltage[0]", "context": "Cell"},
                              {"topic": "docked", "type": "std_msgs/Bool", "context": "Docked", "qos": {"reliability": "reliable", "depth": 5}},
                              {"topic": "bump", "type": "std_msgs/Empty", "as": "event", "context": "Bump"}],
                 "roqme": {"contexts": ["RoqmeDoubleContext"], "estimates": "in"}}
                """);
        assertEquals(7, c.domain());
        assertEquals(List.of("header", "stamp", "sec"), c.contexts().get(0).path());
        assertEquals(List.of("cell_voltage", 0), c.contexts().get(1).path());
        assertEquals(ContextType.BOOLEAN, c.contexts().get(2).as());
        assertEquals(new Qos(true, false, 5), c.contexts().get(2).qos());
        assertEquals(ContextType.EVENT, c.contexts().get(3).as());
        assertEquals(List.of("RoqmeDoubleContext"), c.roqme().contextTopics());
        assertEquals("Roqme DDS partition", c.roqme().partition());
        assertTrue("keyed by name as in RoQME's IDL unless told otherwise", c.roqme().keyed());
        assertEquals(false, read("{\"roqme\": {\"keyed\": false}}").roqme().keyed());
    }

    @Test
    public void errorsCarryLineColumnAndPointer() {
        String json = """
                {"contexts": [
                  {"topic": "battery_state", "type": "sensor_msgs/BatteryState",
                   "field": "percent", "context": "BatteryLevel"}]}
                """;
        String e = error(json);
        assertTrue(e, e.startsWith("bridge.json:3:13: error [dds-config]: /contexts/0/field: sensor_msgs/BatteryState has no value field \"percent\""));
        assertTrue("lists the fields", e.contains("percentage") && e.contains("header.stamp.sec") && e.contains("cell_voltage[i]"));
        assertTrue(error("{\"decisions\": [{\"varpoint\": \"task\", \"topic\": \"rt/miron/task\"}]}"),
                error("{\"decisions\": [{\"varpoint\": \"task\", \"topic\": \"rt/miron/task\"}]}")
                        .startsWith("bridge.json:1:46: error [dds-config]: /decisions/0/topic: give the ROS 2 name without rt/"));
        assertEquals("bridge.json:1:54: error [dds-config]: /contexts/0/type: unknown message type sensor_msgs/Battery (a ROS 2 type as pkg/Name,"
                + " e.g. sensor_msgs/BatteryState, shipped or of a package in \"messages\")",
                error("{\"contexts\": [{\"topic\": \"b\", \"context\": \"B\", \"type\": \"sensor_msgs/Battery\"}]}"));
        assertTrue(error("{\"contexts\": [{\"topic\": \"s\", \"type\": \"std_msgs/String\", \"context\": \"S\", \"scale\": 2}]}")
                .contains("/contexts/0/scale: only a number context can be scaled"));
        assertTrue(error("{\"decisions\": [{\"varpoint\": \"v\", \"topic\": \"t\", \"qos\": {\"durability\": \"durable\"}}]}")
                .contains("/decisions/0/qos/durability: must be volatile or transient_local"));
        assertTrue(error("{\"decisions\": [{\"varpoint\": \"v\", \"topic\": \"t\", \"colour\": 1}]}")
                .contains("/decisions/0/colour: unknown key \"colour\""));
        assertTrue(error("{\"domain\": 300, \"roqme\": {}}").startsWith("bridge.json:1:12: error [dds-config]: /domain: an integer from 0 to 232"));
        assertTrue(error("{\"roqme\": {}, \"roqme\": {}}").contains("duplicate key"));
        assertTrue(error("{\"roqme\": {},}").startsWith("bridge.json:1:"));
        assertTrue(error("{}").contains("nothing to bridge"));
        assertTrue(error("{\"interfaces\": [\"lo\"], \"roqme\": {}}").contains("/interfaces/0: an IPv4 address"));
        assertTrue(error("{\"roqme\": {\"estimates\": \"both\"}}").contains("/roqme/estimates: must be \"out\""));
        assertTrue(error("{\"roqme\": {\"keyed\": \"yes\"}}").startsWith("bridge.json:1:21: error [dds-config]: /roqme/keyed: true or false is expected"));
    }

    private static final String SPEED = """
            {"messages": ["../../../examples/nav2/msgs/nav2_msgs"],
             "decisions": [{"varpoint": "maxVelocity", "topic": "speed_limit", "type": "nav2_msgs/SpeedLimit", "field": "speed_limit",
                            "scale": 0.01, "set": {"percentage": false, "header.frame_id": "map"}, "parameter": "transvel"}%s]}
            """;

    /** Read as if the file were org.miron.dds/src/test/bridge.json: its messages relative to that. */
    private static BridgeConfig readBesideTests(String json) throws Exception {
        return ConfigReader.read(json, RepositoryRoot.resolve("org.miron.dds/src/test/bridge.json"), IhmcTransport.CATALOG, w -> { });
    }

    private static String errorBesideTests(String json) throws Exception {
        try {
            readBesideTests(json);
        } catch (ConfigException e) {
            return e.format("bridge.json");
        }
        fail("accepted: " + json);
        return null;
    }

    @Test
    public void aDecisionIntoAFieldOfALoadedType() throws Exception {
        BridgeConfig c = readBesideTests(SPEED.formatted(""));
        BridgeConfig.DecisionMapping d = c.decisions().get(0);
        assertTrue(c.types().isLoaded("nav2_msgs/SpeedLimit"));
        assertEquals(List.of("speed_limit"), d.path());
        assertEquals(0.01, d.scale(), 0);
        assertEquals("transvel", d.parameter());
        assertTrue(c.answersParameters());
        assertTrue("a header is stamped", d.stamp());
        assertEquals("{\"header\":{\"stamp\":{\"sec\":0,\"nanosec\":0},\"frame_id\":\"map\"},\"percentage\":false,\"speed_limit\":0.0}",
                d.base().toString());
        assertEquals(Qos.LATCHED, d.qos());
        assertTrue(JsonSchemaFile.DDS_BRIDGE.problems(SPEED.formatted("")).isEmpty());
    }

    @Test
    public void decisionFieldErrorsNameTheTypesFields() throws Exception {
        String e = errorBesideTests(SPEED.formatted("").replace("\"field\": \"speed_limit\"", "\"field\": \"limit\""));
        assertTrue(e, e.contains("/decisions/0/field: nav2_msgs/SpeedLimit has no value field \"limit\"; its fields: header.stamp.sec,"
                + " header.stamp.nanosec, header.frame_id, percentage, speed_limit"));
        assertTrue(errorBesideTests(SPEED.formatted("").replace("\"percentage\": false", "\"percentage\": 1"))
                .contains("/decisions/0/set/percentage: \"percentage\" of nav2_msgs/SpeedLimit holds a boolean, not 1"));
        assertTrue(errorBesideTests(SPEED.formatted("").replace("\"header.frame_id\"", "\"header.frame\""))
                .contains("/decisions/0/set/header.frame: nav2_msgs/SpeedLimit has no value field"));
        assertTrue(errorBesideTests(SPEED.formatted("").replace("\"field\": \"speed_limit\"", "\"field\": \"percentage\""))
                .contains("/decisions/0/scale: only a number field can be scaled"));
        assertTrue(errorBesideTests(SPEED.formatted(", {\"varpoint\": \"other\", \"topic\": \"x\", \"type\": \"std_msgs/Float64\","
                + " \"parameter\": \"transvel\"}")).contains("/decisions/1/parameter: parameter transvel is already answered by /decisions/0"));
        assertTrue(errorBesideTests(SPEED.formatted("").replace("nav2_msgs\"]", "no_such_msgs\"]"))
                .contains("/messages/0: no such folder"));
        assertTrue(error("{\"decisions\": [{\"varpoint\": \"v\", \"topic\": \"t\", \"type\": \"nav2_msgs/SpeedLimit\"}]}")
                .contains("/decisions/0/type: unknown message type nav2_msgs/SpeedLimit"));
    }

    @Test
    public void aBadDefinitionIsADdsTypesErrorAtItsLine() throws Exception {
        Path dir = Files.createTempDirectory("bad-msgs");
        Files.createDirectories(dir.resolve("robot_msgs/msg"));
        Files.writeString(dir.resolve("robot_msgs/msg/Battery.msg"), "# the battery\nflaot32 level\n");
        Path config = dir.resolve("bridge.json");
        String json = "{\"messages\": [\"robot_msgs\"], \"contexts\": [{\"topic\": \"b\", \"type\": \"robot_msgs/Battery\","
                + " \"field\": \"level\", \"context\": \"B\"}]}";
        try {
            ConfigReader.read(json, config, IhmcTransport.CATALOG, w -> { });
            fail("accepted");
        } catch (org.miron.dds.types.DefinitionException e) {
            assertEquals(dir.resolve("robot_msgs/msg/Battery.msg") + ":2:1: error [dds-types]: unknown type flaot32 (not a primitive: bool,"
                    + " byte, char, float32, float64, int8 ... uint64, string, wstring; a message type is CamelCase); did you mean float32?", e.format());
        }
        Files.writeString(dir.resolve("robot_msgs/msg/Battery.msg"), "float32 level\n");
        assertEquals("robot_msgs/Battery", ConfigReader.read(json, config, IhmcTransport.CATALOG, w -> { }).contexts().get(0).type());
    }

    @Test
    public void theNav2ExampleFollowsTheSchemaAndIsAccepted() throws Exception {
        Path example = RepositoryRoot.resolve("examples/nav2/bridge.json");
        JsonSchemaFile.DDS_BRIDGE.assertValid(example);
        BridgeConfig c = ConfigReader.read(Files.readString(example), example, IhmcTransport.CATALOG, w -> fail(w));
        assertEquals("speed_limit", c.decisions().get(2).parameter());
        assertEquals(List.of("planner_selector", "controller_selector", "speed_limit"), c.decisions().stream().map(d -> d.topic()).toList());
    }

    @Test
    public void theExampleFollowsTheSchemaAndIsAccepted() throws Exception {
        Path example = RepositoryRoot.resolve("examples/intralogistics/dds/bridge.json");
        JsonSchemaFile.DDS_BRIDGE.assertValid(example);
        BridgeConfig c = ConfigReader.read(Files.readString(example), example, IhmcTransport.CATALOG, w -> fail(w));
        assertEquals(2, c.contexts().size());
        assertEquals(ContextType.ENUM, c.contexts().get(1).as());
        assertEquals("std_msgs/Float64", c.decisions().get(1).type());
        assertEquals("maxVelocity also as Nav2's speed limit", "nav2_msgs/SpeedLimit", c.decisions().get(2).type());
        assertEquals("transvel", c.decisions().get(2).parameter());
        assertFalse(JsonSchemaFile.DDS_BRIDGE.problems("{\"decisions\": [{\"varpoint\": \"v\", \"topic\": \"rt/x\"}]}").isEmpty());
        assertFalse(JsonSchemaFile.DDS_BRIDGE.problems("{\"domain\": 0}").isEmpty());
    }
}
