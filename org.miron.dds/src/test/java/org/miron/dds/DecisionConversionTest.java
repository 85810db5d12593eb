package org.miron.dds;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNull;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.dds.config.BridgeConfig.DecisionMapping;
import org.miron.dds.config.ConfigReader;
import org.miron.dds.transport.IhmcTransport;

/** A decided value into its message field: scaled, rounded for an integer field, refused when the field cannot carry it. */
public class DecisionConversionTest {
    private static final JsonNodeFactory F = JsonNodeFactory.instance;

    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();

    private DecisionMapping mapping(String field, String extra) throws Exception {
        Path dir = tmp.getRoot().toPath();
        Files.createDirectories(dir.resolve("robot_msgs/msg"));
        Files.writeString(dir.resolve("robot_msgs/msg/Command.msg"), "std_msgs/Header header\nuint8 level\nstring mode\nbool on\nfloat64 speed\n");
        String json = "{\"messages\": [\"robot_msgs\"], \"decisions\": [{\"varpoint\": \"v\", \"topic\": \"cmd\", \"type\": \"robot_msgs/Command\","
                + " \"field\": \"" + field + "\"" + extra + "}]}";
        return ConfigReader.read(json, dir.resolve("bridge.json"), IhmcTransport.CATALOG, w -> { }).decisions().get(0);
    }

    @Test
    public void numbersAreScaledAndRoundedIntoIntegerFields() throws Exception {
        DecisionMapping d = mapping("level", ", \"scale\": 0.5");
        assertEquals(F.numberNode(42L), DecisionConversion.value(d, F.numberNode(83.0)));
        assertNull("text cannot go into a uint8", DecisionConversion.value(d, F.textNode("fast")));
        DecisionMapping s = mapping("speed", ", \"scale\": 0.01");
        assertEquals(0.83, DecisionConversion.value(s, F.numberNode(83)).asDouble(), 1e-12);
    }

    @Test
    public void enumLiteralsGoToStringFieldsAndBooleansToBoolFields() throws Exception {
        assertEquals("dock", DecisionConversion.value(mapping("mode", ""), F.textNode("dock")).asText());
        assertEquals("83", DecisionConversion.value(mapping("mode", ""), F.numberNode(83)).asText());
        assertEquals(F.booleanNode(true), DecisionConversion.value(mapping("on", ""), F.booleanNode(true)));
        assertNull(DecisionConversion.value(mapping("on", ""), F.numberNode(1)));
    }

    @Test
    public void theMessageHasTheSetFieldsAndTheDecisionsTimeAsItsStamp() throws Exception {
        DecisionMapping d = mapping("speed", ", \"set\": {\"mode\": \"auto\", \"header.frame_id\": \"map\"}");
        var m = DecisionConversion.message(d, F.numberNode(0.5), 1_700_000_000_250L);
        assertEquals("{\"header\":{\"stamp\":{\"sec\":1700000000,\"nanosec\":250000000},\"frame_id\":\"map\"},\"level\":0,\"mode\":\"auto\","
                + "\"on\":false,\"speed\":0.5}", m.toString());
        assertEquals("the mapping's base is left as it was", 0.0, d.base().path("speed").asDouble(), 0);
    }
}
