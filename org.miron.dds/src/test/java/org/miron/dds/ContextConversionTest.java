package org.miron.dds;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import org.junit.Test;
import org.miron.dds.config.BridgeConfig;
import org.miron.dds.config.ConfigReader;
import org.miron.dds.transport.IhmcTransport;

/** Samples (as the transport hands them over) to roqme.context bodies, and the ones refused. */
public class ContextConversionTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    private static BridgeConfig.ContextMapping mapping(String json) throws Exception {
        return ConfigReader.read("{\"contexts\": [" + json + "]}", IhmcTransport.CATALOG).contexts().get(0);
    }

    private static String refusal(BridgeConfig.ContextMapping m, String sample) throws Exception {
        try {
            ContextConversion.fromRos(m, JSON.readTree(sample), 1);
        } catch (Rejected e) {
            return e.getMessage();
        }
        fail("accepted " + sample);
        return null;
    }

    @Test
    public void aScaledNestedNumber() throws Exception {
        BridgeConfig.ContextMapping m = mapping("{\"topic\": \"b\", \"type\": \"sensor_msgs/BatteryState\", \"field\": \"cell_voltage[1]\","
                + " \"scale\": 1000, \"context\": \"Cell\", \"namespace\": \"N\"}");
        JsonNode b = ContextConversion.fromRos(m, JSON.readTree("{\"cell_voltage\": [3.6, 3.7]}"), 42);
        assertEquals("{\"name\":\"Cell\",\"namespace\":\"N\",\"type\":\"number\",\"value\":3700.0,\"time\":42}", b.toString());
        assertEquals("no second cell: missing", "no field cell_voltage[1]", refusal(m, "{\"cell_voltage\": [3.6]}"));
    }

    @Test
    public void wrongTypesAndNonFiniteNumbersAreRefused() throws Exception {
        BridgeConfig.ContextMapping pct = mapping("{\"topic\": \"b\", \"type\": \"sensor_msgs/BatteryState\", \"field\": \"percentage\", \"context\": \"B\"}");
        assertEquals("percentage is NaN, not a finite number", refusal(pct, "{\"percentage\": NaN}".replace("NaN", "\"NaN\"")));
        BridgeConfig.ContextMapping text = mapping("{\"topic\": \"d\", \"type\": \"std_msgs/String\", \"as\": \"number\", \"context\": \"D\"}");
        assertEquals("data is \"far\", not a number", refusal(text, "{\"data\": \"far\"}"));
        assertEquals(1.5, ContextConversion.fromRos(text, JSON.readTree("{\"data\": \" 1.5 \"}"), 1).path("value").asDouble(), 0);
        BridgeConfig.ContextMapping literal = mapping("{\"topic\": \"s\", \"type\": \"std_msgs/String\", \"context\": \"Space\"}");
        assertEquals("enum", ContextConversion.fromRos(literal, JSON.readTree("{\"data\": \"HIGH\"}"), 1).path("type").asText());
        assertTrue(refusal(literal, "{\"data\": \"very high\"}").endsWith("not an enum literal"));
        BridgeConfig.ContextMapping flag = mapping("{\"topic\": \"f\", \"type\": \"std_msgs/Bool\", \"context\": \"Docked\"}");
        assertEquals("data is 1, not a boolean", refusal(flag, "{\"data\": 1}"));
    }

    @Test
    public void roqmeContextStructs() throws Exception {
        assertEquals("{\"name\":\"BatteryLevel\",\"type\":\"number\",\"value\":42.5,\"time\":1}", ContextConversion.fromRoqme(
                "RoqmeDoubleContext", "", JSON.readTree("{\"name\": \"BatteryLevel\", \"value\": [42.5, 1]}"), 1).toString());
        assertEquals("true", ContextConversion.fromRoqme("RoqmeEventContext", "N",
                JSON.readTree("{\"name\": \"Delivered\", \"value\": [\"x\"]}"), 1).path("value").toString());
        try {
            ContextConversion.fromRoqme("RoqmeBoolContext", "", JSON.readTree("{\"name\": \"Docked\", \"value\": []}"), 1);
            fail();
        } catch (Rejected e) {
            assertEquals("Docked has no value", e.getMessage());
        }
    }
}
