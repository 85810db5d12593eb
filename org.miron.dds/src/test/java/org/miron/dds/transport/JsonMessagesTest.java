package org.miron.dds.transport;

import static org.junit.Assert.assertEquals;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import org.junit.Test;
import us.ihmc.pubsub.TopicDataType;
import us.ihmc.pubsub.common.SerializedPayload;

/** JSON -> message -> CDR -> message -> JSON through the library's types and ours: what the peer sees is what was meant. */
public class JsonMessagesTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    @SuppressWarnings("unchecked")
    private static JsonNode roundTrip(String type, String json) throws Exception {
        TopicDataType<Object> t = (TopicDataType<Object>) Types.lookup(type);
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
        assertEquals("RoqmeDDSTopics::RoqmeEstimate", Types.lookup("RoqmeEstimate").getName());
        assertEquals("std_msgs::msg::dds_::String_", Types.lookup("std_msgs/String").getName());
        assertEquals(null, Types.lookup("std_msgs/Nothing"));
        assertEquals(null, Types.lookup("java/lang/String"));
    }
}
