package org.miron.runtime.player;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Endpoints;
import org.miron.runtime.Json;
import org.miron.runtime.broker.Broker;
import org.miron.runtime.bus.Topics;
import org.miron.testkit.runtime.BusProbe;

public class ScenarioPlayerTest {
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();

    @Test
    public void playsStepsInTimeOrderOnTheBus() throws Exception {
        Path file = tmp.newFile("scenario.json").toPath();
        Files.writeString(file, "[\n"
                + " {\"at\": 300, \"estimate\": {\"name\": \"power_autonomy\", \"namespace\": \"Intralogistics\", \"value\": 0.2}},\n"
                + " {\"at\": 0, \"context\": {\"name\": \"BatteryLevel\", \"namespace\": \"Intralogistics\", \"type\": \"number\", \"value\": 80}},\n"
                + " {\"at\": 100, \"estimate\": {\"name\": \"safety\", \"namespace\": \"Intralogistics\", \"value\": 0.9, \"time\": 42}}\n"
                + "]");
        Scenario scenario = Scenario.load(file);
        assertEquals(List.of(0L, 100L, 300L), scenario.steps().stream().map(Scenario.Step::at).toList());
        Endpoints ep = Endpoints.freeLoopback();
        try (Broker broker = new Broker(ep).start();
                BusProbe probe = new BusProbe(ep.busOut(), "roqme.");
                ScenarioPlayer player = new ScenarioPlayer(scenario, 0.1, ep.busIn())) {
            assertEquals(3, player.play(10_000));
            JsonNode power = probe.await(Topics.ESTIMATE, b -> b.path("name").asText().equals("power_autonomy"), 10_000);
            assertNotNull(power);
            assertTrue("time filled in", power.path("time").asLong() > 0);
            JsonNode safety = probe.await(Topics.ESTIMATE, b -> b.path("name").asText().equals("safety"), 10_000);
            assertEquals("given time kept", 42, safety.path("time").asLong());
            assertNotNull(probe.await(Topics.CONTEXT, b -> b.path("value").asDouble() == 80.0, 10_000));
            List<String> order = probe.messages(Topics.ESTIMATE).stream().map(m -> m.body().path("name").asText()).toList();
            assertEquals(List.of("safety", "power_autonomy"), order.subList(order.size() - 2, order.size()));
        }
    }

    @Test
    public void rejectsMalformedScenarios() {
        for (String bad : new String[] {"{}", "[{\"at\": -1, \"estimate\": {}}]", "[{\"at\": 1}]",
                "[{\"at\": 1, \"estimate\": {}, \"context\": {}}]", "[{\"estimate\": {}}]"}) {
            try {
                Scenario.parse(Json.MAPPER.readTree(bad));
                fail("accepted " + bad);
            } catch (IllegalArgumentException expected) {
                assertTrue(expected.getMessage().length() > 0);
            } catch (Exception e) {
                throw new AssertionError(e);
            }
        }
    }
}
