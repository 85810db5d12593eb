package org.miron.dds.types;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assume.assumeTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.math.BigDecimal;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HexFormat;
import java.util.Iterator;
import java.util.List;
import org.junit.AfterClass;
import org.junit.BeforeClass;
import org.junit.Test;
import org.miron.dds.CodecPeers;
import org.miron.testkit.RepositoryRoot;

/**
 * Our CDR against Cyclone DDS's (cyclonedds-python, an independent implementation; dds_peer.py
 * declares the same types from their field lists): what we write Cyclone reads, byte for byte what
 * it writes itself in XCDR1, and what it writes in XCDR1, XCDR2 plain and XCDR2 delimited we read.
 * Every field kind: primitives of each size (alignment after a uint8 included), strings bounded
 * and not, fixed, bounded and unbounded arrays of primitives, strings and nested messages.
 */
public class CdrOracleTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    static final String ALL_KINDS = """
            {"small": 200, "big": 1.0E300, "flag": true, "i8": -128, "i16": -32768, "u16": 65535, "i32": -2147483648,
             "u32": 4294967295, "i64": -9223372036854775808, "u64": 18446744073709551615, "f32": 0.15625, "b": 255, "c": 65,
             "text": "héllo, wörld", "short_text": "8 chars!", "fixed": [1.5, -2.25, 3.0], "bounded": [1, 2, 3, 4],
             "unbounded": [-1, 0, 1, 32767], "names": ["", "a", "bcd"], "fixed_names": ["abcde", "x"], "flags": [true, false, true],
             "points": [{"tag": 1, "x": 0.5, "y": -0.5}, {"tag": 2, "x": 1.5, "y": 2.5}],
             "fixed_points": [{"tag": 3, "x": 3.5, "y": 4.5}, {"tag": 4, "x": 5.5, "y": 6.5}],
             "some_points": [{"tag": 5, "x": 7.5, "y": 8.5}], "stamp": {"sec": 1700000000, "nanosec": 999999999}, "last": 9}
            """;
    private static CyclonePeerHandle peer;
    private static TypeRegistry types;

    /** The codec peer, or why the test is skipped. */
    record CyclonePeerHandle(AutoCloseable peer, String skip) {
    }

    @BeforeClass
    public static void start() throws Exception {
        types = MessagePackages.load(List.of(fixture("test_types"), fixture("my_robot_msgs"),
                RepositoryRoot.resolve("examples/nav2/msgs/nav2_msgs")), t -> false, w -> { });
        Path dir = Files.createTempDirectory("cdr-oracle");
        peer = new CyclonePeerHandle(CodecPeers.start(dir), CodecPeers.skip());
    }

    @AfterClass
    public static void stop() throws Exception {
        if (peer != null && peer.peer() != null) {
            peer.peer().close();
        }
    }

    static Path fixture(String name) throws Exception {
        return Path.of(CdrOracleTest.class.getResource("/org/miron/dds/msgs/" + name + "/msg").toURI()).getParent();
    }

    private static void assumePeer() {
        assumeTrue(peer.skip(), peer.skip() == null);
    }

    private static byte[] ours(String type, JsonNode message) {
        return CdrWriter.write(types, types.get(type), message);
    }

    private static ObjectNode read(String type, byte[] payload) throws CdrReader.Undecodable {
        return CdrReader.read(types, types.get(type), payload, payload.length);
    }

    @Test
    public void cycloneReadsWhatWeWriteAndWritesTheSameBytes() throws Exception {
        assumePeer();
        JsonNode m = JSON.readTree(ALL_KINDS);
        byte[] b = ours("miron_test_msgs/AllKinds", m);
        assertSameMessage(m, CodecPeers.decode("miron_test_msgs/AllKinds", HexFormat.of().formatHex(b)));
        byte[] theirs = HexFormat.of().parseHex(CodecPeers.encode("miron_test_msgs/AllKinds", ALL_KINDS, false, false));
        assertEquals("encapsulation CDR_LE", "0001", HexFormat.of().formatHex(theirs, 0, 2));
        // bytes 2-3 are options (Cyclone counts its trailing padding there); the body must be identical
        assertArrayEquals(java.util.Arrays.copyOfRange(theirs, 4, theirs.length), java.util.Arrays.copyOfRange(b, 4, b.length));
    }

    @Test
    public void weReadCycloneInXcdr1AndBothXcdr2Forms() throws Exception {
        assumePeer();
        JsonNode m = JSON.readTree(ALL_KINDS);
        for (boolean[] form : new boolean[][] {{false, false}, {true, false}, {true, true}}) {
            String hex = CodecPeers.encode("miron_test_msgs/AllKinds", ALL_KINDS, form[0], form[1]);
            byte[] b = HexFormat.of().parseHex(hex);
            String how = (form[0] ? "XCDR2" : "XCDR1") + (form[1] ? " delimited" : "") + " encapsulation " + hex.substring(0, 4);
            assertEquals(how, form[0] ? (form[1] ? "0009" : "0007") : "0001", hex.substring(0, 4));
            assertSameMessage(m, read("miron_test_msgs/AllKinds", b));
        }
    }

    @Test
    public void defaultsAreTheDefinitionsAndRos2Zeros() throws Exception {
        assumePeer();
        for (String type : List.of("miron_test_msgs/AllKinds", "my_robot_msgs/PowerStatus", "nav2_msgs/SpeedLimit")) {
            ObjectNode template = types.template(types.get(type));
            JsonNode cyclone = CodecPeers.decode(type, CodecPeers.encode(type, "{}", false, false));
            assertSameMessage(cyclone, template);
            assertSameMessage(cyclone, CodecPeers.decode(type, HexFormat.of().formatHex(ours(type, template))));
        }
        assertEquals(7, types.template(types.get("miron_test_msgs/AllKinds")).path("small").asInt());
        assertEquals(48.0, types.template(types.get("my_robot_msgs/PowerStatus")).path("voltage").asDouble(), 0);
        assertEquals(true, types.template(types.get("my_robot_msgs/PowerStatus")).path("charger").path("reachable").asBoolean());
    }

    @Test
    public void theRobotsTypesBothWays() throws Exception {
        assumePeer();
        String power = """
                {"header": {"stamp": {"sec": 12, "nanosec": 34}, "frame_id": "base_link"}, "charge_percent": 42.5, "voltage": 47.25,
                 "status": 1, "charger": {"dock_id": "dock-7", "reachable": false, "last_seen": {"sec": 5, "nanosec": 6}},
                 "cell_voltages": [3.5, 3.75]}""";
        String speed = "{\"header\": {\"stamp\": {\"sec\": 1, \"nanosec\": 2}, \"frame_id\": \"map\"}, \"percentage\": false, \"speed_limit\": 0.83}";
        for (String[] c : new String[][] {{"my_robot_msgs/PowerStatus", power}, {"nav2_msgs/SpeedLimit", speed}}) {
            JsonNode m = JSON.readTree(c[1]);
            assertSameMessage(m, CodecPeers.decode(c[0], HexFormat.of().formatHex(ours(c[0], m))));
            assertSameMessage(m, read(c[0], HexFormat.of().parseHex(CodecPeers.encode(c[0], c[1], false, false))));
            assertSameMessage(m, read(c[0], HexFormat.of().parseHex(CodecPeers.encode(c[0], c[1], true, true))));
        }
    }

    @Test
    public void aPayloadThatIsNotTheTypeIsRefusedWithTheReason() throws Exception {
        byte[] b = ours("nav2_msgs/SpeedLimit", JSON.readTree("{\"header\": {\"frame_id\": \"map\"}, \"speed_limit\": 1.0}"));
        assertRefused("ends before", () -> read("nav2_msgs/SpeedLimit", java.util.Arrays.copyOf(b, b.length - 3)));
        byte[] pl = b.clone();
        pl[1] = 3; // PL_CDR_LE: parameter lists are not plain CDR
        assertRefused("not plain CDR", () -> read("nav2_msgs/SpeedLimit", pl));
        byte[] badBool = b.clone();
        badBool[4 + 8 + 4 + 4] = 7; // percentage, after stamp (8) and frame_id "map\0" (4 + 4)
        assertRefused("a bool is 0 or 1", () -> read("nav2_msgs/SpeedLimit", badBool));
        byte[] hugeString = b.clone();
        hugeString[4 + 8 + 3] = 0x7f; // frame_id's length
        assertRefused("a string of", () -> read("nav2_msgs/SpeedLimit", hugeString));
        assertRefused("at most 8 characters", () -> read("miron_test_msgs/AllKinds",
                ours("miron_test_msgs/AllKinds", JSON.readTree("{}")).length > 0 ? tooLong() : null));
    }

    /** An AllKinds whose bounded string Cyclone would refuse to write: ours with the bound lifted. */
    private static byte[] tooLong() throws Exception {
        TypeRegistry loose = MessagePackages.load(List.of(fixture("test_types")), t -> false, w -> { });
        MsgType t = loose.get("miron_test_msgs/AllKinds");
        java.util.List<MsgField> fields = new java.util.ArrayList<>();
        for (MsgField f : t.fields()) {
            fields.add(f.name().equals("short_text") ? new MsgField(f.name(), new FieldType(Primitive.STRING, null, -1, FieldType.Array.NONE, -1),
                    null, f.line(), f.column()) : f);
        }
        MsgType unbounded = new MsgType(t.pkg(), t.name(), fields, t.constants(), t.file());
        return CdrWriter.write(loose, unbounded, JSON.readTree("{\"short_text\": \"nine chars\"}"));
    }

    interface Decode {
        Object run() throws Exception;
    }

    private static void assertRefused(String why, Decode d) throws Exception {
        try {
            d.run();
        } catch (CdrReader.Undecodable e) {
            assertEquals(e.getMessage(), true, e.getMessage().contains(why));
            return;
        }
        throw new AssertionError("decoded, though " + why);
    }

    /** Equal trees, numbers by value (Cyclone's JSON has 4294967295 as a long, ours maybe as a BigInteger; floats as decimals). */
    static void assertSameMessage(JsonNode expected, JsonNode actual) {
        same("", expected, actual);
    }

    private static void same(String path, JsonNode e, JsonNode a) {
        if (e.isNumber() && a.isNumber()) {
            assertEquals(path + ": " + e + " vs " + a, 0, new BigDecimal(e.asText()).compareTo(new BigDecimal(a.asText())));
        } else if (e.isObject()) {
            assertEquals(path + " fields", fieldNames(e), fieldNames(a));
            e.fields().forEachRemaining(f -> same(path + "." + f.getKey(), f.getValue(), a.get(f.getKey())));
        } else if (e.isArray()) {
            assertEquals(path + " length: " + e + " vs " + a, e.size(), a.size());
            for (int i = 0; i < e.size(); i++) {
                same(path + "[" + i + "]", e.get(i), a.get(i));
            }
        } else {
            assertEquals(path, e, a);
        }
    }

    private static List<String> fieldNames(JsonNode n) {
        List<String> l = new java.util.ArrayList<>();
        for (Iterator<String> it = n.fieldNames(); it.hasNext();) {
            l.add(it.next());
        }
        return l;
    }
}
