package org.miron.dds.transport;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.fail;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.ByteBuffer;
import org.junit.Test;
import us.ihmc.pubsub.TopicDataType;
import us.ihmc.pubsub.common.SerializedPayload;

/** JSON -> message -> CDR -> message -> JSON through the library's types and ours: what the peer sees is what was meant. */
public class JsonMessagesTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    @SuppressWarnings("unchecked")
    private static JsonNode roundTrip(String type, String json) throws Exception {
        TopicDataType<Object> t = (TopicDataType<Object>) Types.lookup(type, false);
        Object m = JsonIn.fill(t, JSON.readTree(json));
        SerializedPayload payload = new SerializedPayload(t.getTypeSize());
        t.serialize(m, payload);
        Object back = t.createData();
        t.deserialize(payload, back);
        return JsonOut.of(t, back);
    }

    @Test
    public void batteryStateKeepsNestedFieldsSequencesAndFloats() throws Exception {
        JsonNode b = roundTrip("sensor_msgs/BatteryState",
                "{\"header\": {\"stamp\": {\"sec\": 5}, \"frame_id\": \"base\"}, \"percentage\": 0.2, \"cell_voltage\": [3.6, 3.7], \"present\": true}");
        assertEquals(5, b.path("header").path("stamp").path("sec").asInt());
        assertEquals("base", b.path("header").path("frame_id").asText());
        assertEquals("a float as its shortest decimal", "0.2", b.path("percentage").toString());
        assertEquals("[3.6,3.7]", b.path("cell_voltage").toString());
        assertEquals(true, b.path("present").asBoolean());
        assertEquals("absent fields keep their defaults", "", b.path("serial_number").asText());
    }

    @Test
    public void roqmeTypes() throws Exception {
        assertEquals("{\"name\":\"power_autonomy\",\"value\":0.25}",
                roundTrip("RoqmeEstimate", "{\"name\": \"power_autonomy\", \"value\": 0.25}").toString());
        assertEquals("{\"name\":\"FreeSpace\",\"value\":[\"HIGH\",\"LOW\"]}",
                roundTrip("RoqmeEnumContext", "{\"name\": \"FreeSpace\", \"value\": [\"HIGH\", \"LOW\"]}").toString());
        assertEquals("{\"name\":\"Count\",\"value\":[-3,4]}", roundTrip("RoqmeIntContext", "{\"name\": \"Count\", \"value\": [-3, 4]}").toString());
        assertEquals("RoqmeDDSTopics::RoqmeEstimate", Types.lookup("RoqmeEstimate", false).getName());
        assertEquals("the keyed type has the same name", "RoqmeDDSTopics::RoqmeEstimate", Types.lookup("RoqmeEstimate", true).getName());
        assertEquals("std_msgs::msg::dds_::String_", Types.lookup("std_msgs/String", false).getName());
        assertEquals("ROS 2 types have no key", null, Types.lookup("std_msgs/String", true));
        assertEquals(null, Types.lookup("std_msgs/Nothing", false));
        assertEquals(null, Types.lookup("java/lang/String", false));
    }

    @SuppressWarnings("unchecked")
    private static String keyHash(String type, boolean keyed, String json) throws Exception {
        TopicDataType<Object> t = (TopicDataType<Object>) Types.lookup(type, keyed);
        ByteBuffer key = ByteBuffer.allocateDirect(16); // as the library hands it to getKey
        t.getKey(JsonIn.fill(t, JSON.readTree(json)), key);
        StringBuilder hex = new StringBuilder();
        for (int i = 0; i < key.position(); i++) {
            hex.append(String.format("%02x", key.get(i)));
        }
        return hex.toString();
    }

    /** The RTPS key hash of the key name; expected values from Python's hashlib over the big-endian CDR of the string. */
    @Test
    public void keyHashIsTheMd5OfTheBigEndianName() throws Exception {
        assertEquals("ff4ee5dae97e67e23fcc3a6b60305aca", keyHash("RoqmeEstimate", true, "{\"name\": \"safety\", \"value\": 0.5}"));
        assertEquals("the value is no part of the key", "ff4ee5dae97e67e23fcc3a6b60305aca",
                keyHash("RoqmeEstimate", true, "{\"name\": \"safety\", \"value\": 0.9}"));
        assertEquals("UTF-8", "e3d9ac7c9d8c45c7f4e41421414c7b0b", keyHash("RoqmeDoubleContext", true, "{\"name\": \"\u00c5land\", \"value\": [1]}"));
        assertEquals("no key for an unkeyed type", "", keyHash("RoqmeEstimate", false, "{\"name\": \"safety\"}"));
    }

    @Test
    public void aKeyedProfileSaysWithKey() throws Exception {
        String xml = "<data_writer profile_name=\"p\">\n<topic>\n<name>RoqmeEstimate</name>\n</topic>\n</data_writer>";
        assertEquals("<data_writer profile_name=\"p\">\n<topic><kind>WITH_KEY</kind>\n<name>RoqmeEstimate</name>\n</topic>\n</data_writer>",
                IhmcTransport.withKey(xml));
        try {
            IhmcTransport.withKey("<data_writer/>");
            fail("a profile without a topic is refused");
        } catch (java.io.IOException expected) {
            // refused
        }
    }
}
