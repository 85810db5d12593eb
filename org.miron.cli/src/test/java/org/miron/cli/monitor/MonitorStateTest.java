package org.miron.cli.monitor;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import org.junit.Test;
import org.miron.runtime.bus.Topics;

/** The live page's state follows miron.requirement (the latest events) and miron.decision's explanations, each handed to the pages. */
public class MonitorStateTest {
    private static byte[] bytes(String s) {
        return s.getBytes(StandardCharsets.UTF_8);
    }

    @Test
    public void requirementEventsAreKeptLatestLastAndBroadcast() {
        MonitorState state = new MonitorState(LiveMonitor.plainNames());
        List<MonitorState.Event> sent = new ArrayList<>();
        state.subscribe(sent::add);
        for (int i = 0; i < MonitorState.REQUIREMENT_EVENTS + 5; i++) {
            state.onBus(Topics.REQUIREMENT, bytes("{\"name\":\"r" + i + "\",\"verdict\":\"violated\",\"time\":" + i
                    + ".5,\"detected\":" + i + ".5,\"values\":{\"roqme.x\":1.0}}"));
        }
        state.onBus(Topics.REQUIREMENT_STATUS, bytes("{\"time\":3,\"requirements\":{},\"counters\":{}}")); // not an event
        state.onBus(Topics.REQUIREMENT, bytes("{\"verdict\":\"met\"}")); // no name: malformed
        JsonNode snapshot = state.snapshot();
        JsonNode events = snapshot.path("requirements");
        assertEquals(MonitorState.REQUIREMENT_EVENTS, events.size());
        assertEquals("r5", events.get(0).path("name").asText());
        assertEquals("r24", events.get(events.size() - 1).path("name").asText());
        assertEquals(1, snapshot.path("rejected").asInt());
        long told = sent.stream().filter(e -> e.name().equals("requirement")).count();
        assertEquals(MonitorState.REQUIREMENT_EVENTS + 5, told);
        assertTrue(sent.get(sent.size() - 1).data().contains("\"name\":\"r24\""));
    }

    @Test
    public void aDecisionsExplanationIsKeptPerVarpointAndBroadcast() {
        MonitorState state = new MonitorState(LiveMonitor.plainNames());
        List<MonitorState.Event> sent = new ArrayList<>();
        state.subscribe(sent::add);
        state.onBus(Topics.DECISION, bytes("{\"seq\":7,\"decisions\":{\"task\":\"dock\",\"speed\":0.5},\"changed\":[\"task\"],"
                + "\"why\":{\"task\":{\"because\":\"rule noBattery (BatteryLevel < 20)\",\"rules\":[\"noBattery\"]}}}"));
        JsonNode task = state.snapshot().path("explanations").path("task");
        assertEquals("dock", task.path("value").asText());
        assertEquals("rule noBattery (BatteryLevel < 20)", task.path("because").asText());
        assertEquals(7, task.path("seq").asInt());
        assertTrue("only changed varpoints are explained", state.snapshot().path("explanations").path("speed").isMissingNode());
        assertTrue(sent.stream().anyMatch(e -> e.name().equals("explanation") && e.data().contains("noBattery")));
    }
}
