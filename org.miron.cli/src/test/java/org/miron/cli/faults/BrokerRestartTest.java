package org.miron.cli.faults;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import org.junit.After;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Endpoints;
import org.miron.runtime.Json;
import org.miron.runtime.bus.BusClient;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.engine.Engine;
import org.miron.runtime.engine.IoModel;
import org.miron.runtime.player.Scenario;
import org.miron.runtime.player.ScenarioPlayer;
import org.miron.testkit.runtime.BusProbe;
import org.miron.testkit.runtime.EngineFixture;
import org.miron.testkit.runtime.TestbotRules;

/**
 * Issue 10, item 5: the broker process is killed (-9) and restarted with an empty cache. Without
 * anyone acting, the engine re-publishes its decisions and status and the player its estimates,
 * so a subscriber joining after the restart sees the current decision and inputs, and the
 * engine keeps adapting. With {@code --cache-file} the new broker also replays what publishers
 * that are gone had published.
 */
public class BrokerRestartTest {
    private static final long TIMEOUT = EngineFixture.TIMEOUT;
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();
    private EngineFixture f;
    private RuntimeProcess broker;
    private Engine engine;
    private ScenarioPlayer player;
    private Thread playing;
    private BusProbe before;
    private BusProbe after;

    @After
    public void tearDown() throws Exception {
        for (AutoCloseable c : new AutoCloseable[] {after, before, player, engine, broker}) {
            if (c != null) {
                c.close();
            }
        }
        if (f != null) {
            f.close();
        }
    }

    private RuntimeProcess startBroker(Endpoints ep, String... more) throws Exception {
        List<String> args = new ArrayList<>(List.of("broker", "--request", ep.request(), "--skill", ep.skill(),
                "--bus-in", ep.busIn(), "--bus-out", ep.busOut()));
        args.addAll(List.of(more));
        RuntimeProcess p = RuntimeProcess.start(tmp.getRoot().toPath(), "broker", args.toArray(new String[0]));
        assertTrue("broker up:\n" + p.output(), p.awaitOutput("broker: requests", TIMEOUT));
        return p;
    }

    @Test
    public void componentsReannounceTheirStateToARestartedBroker() throws Exception {
        f = new EngineFixture(tmp.getRoot().toPath());
        Endpoints ep = f.endpoints;
        broker = startBroker(ep);
        engine = new Engine(IoModel.load(f.ioJson), new TestbotRules(), f.options()).start();
        // the player's last step stays pending: it is alive and owns power_autonomy = 0.2
        player = new ScenarioPlayer(Scenario.parse(Json.MAPPER.readTree("[{\"at\":0,\"estimate\":{\"name\":"
                + "\"power_autonomy\",\"namespace\":\"Intralogistics\",\"value\":0.2}},{\"at\":600000,\"estimate\":"
                + "{\"name\":\"safety\",\"namespace\":\"Intralogistics\",\"value\":0.9}}]")), 1.0, ep.busIn());
        playing = new Thread(() -> {
            try {
                player.play(TIMEOUT);
            } catch (InterruptedException | RuntimeException e) {
                // closed by the test
            }
        });
        playing.setDaemon(true);
        playing.start();
        before = new BusProbe(ep.busOut(), "miron.");
        assertNotNull("docking before the restart", before.await(Topics.VARIANT_PREFIX + "task",
                b -> b.path("value").asText().equals("dock"), TIMEOUT));
        long seq = engine.status().get("solved");

        broker.kill();
        broker.close();
        broker = startBroker(ep);

        after = new BusProbe(ep.busOut(), "miron.", "roqme.");
        JsonNode task = after.await(Topics.VARIANT_PREFIX + "task", b -> true, TIMEOUT);
        assertNotNull("a subscriber joining after the restart gets the current task", task);
        assertEquals("dock", task.path("value").asText());
        JsonNode decision = after.await(Topics.DECISION, b -> true, TIMEOUT);
        assertNotNull("and the current decision", decision);
        assertEquals("the same decision, not a new one", seq, decision.path("seq").asLong());
        assertNotNull("and the engine's status", after.await(Topics.STATUS, b -> true, TIMEOUT));
        assertNotNull("the player re-announced its estimate", after.await(Topics.ESTIMATE,
                b -> b.path("name").asText().equals("power_autonomy") && b.path("value").asDouble() == 0.2, TIMEOUT));

        // still adapting through the new broker
        try (var input = new BusClient("input", ep.busIn(), null, List.of(), (t, b) -> { })
                .start()) {
            assertTrue(input.awaitReady(TIMEOUT));
            input.publish(Topics.ESTIMATE, "{\"name\":\"power_autonomy\",\"namespace\":\"Intralogistics\",\"value\":0.8}");
            assertNotNull("the engine adapts after the restart", after.await(Topics.VARIANT_PREFIX + "task",
                    b -> b.path("value").asText().equals("pickDeliverCharge"), TIMEOUT));
        }
    }

    @Test
    public void withACacheFileARestartedBrokerReplaysWhatItHadFromPublishersGoneSince() throws Exception {
        f = new EngineFixture(tmp.getRoot().toPath());
        Endpoints ep = f.endpoints;
        Path file = tmp.getRoot().toPath().resolve("cache.json");
        broker = startBroker(ep, "--cache-file", file.toString());
        try (BusClient once = new BusClient("once", ep.busIn(), null, List.of(), (t, b) -> { }).start()) {
            assertTrue(once.awaitReady(TIMEOUT));
            once.publish(Topics.ESTIMATE, "{\"name\":\"power_autonomy\",\"namespace\":\"Intralogistics\",\"value\":0.2}");
            once.publish(Topics.ESTIMATE, "{\"name\":\"power_autonomy\",\"namespace\":\"Intralogistics\",\"value\":9}");
            assertTrue(once.flush(TIMEOUT));
        } // this publisher is gone: nobody will re-announce the estimate
        long end = System.currentTimeMillis() + TIMEOUT;
        while (!snapshotHolds(file, "power_autonomy") && System.currentTimeMillis() < end) {
            Thread.sleep(20);
        }
        assertTrue("snapshot written", snapshotHolds(file, "power_autonomy"));

        broker.kill();
        broker.close();
        broker = startBroker(ep, "--cache-file", file.toString());
        after = new BusProbe(ep.busOut(), "roqme.");
        JsonNode power = after.await(Topics.ESTIMATE, b -> b.path("name").asText().equals("power_autonomy"), TIMEOUT);
        assertNotNull("replayed from the snapshot after kill -9 and restart", power);
        assertEquals("the valid value", 0.2, power.path("value").asDouble(), 0.0);
        engine = new Engine(IoModel.load(f.ioJson), new TestbotRules(), f.options()).start();
        before = new BusProbe(ep.busOut(), "miron.");
        assertNotNull("an engine started now docks", before.await(Topics.VARIANT_PREFIX + "task",
                b -> b.path("value").asText().equals("dock"), TIMEOUT));
    }

    private static boolean snapshotHolds(Path file, String text) {
        try {
            for (JsonNode entry : Json.MAPPER.readTree(file.toFile())) {
                for (JsonNode frame : entry) {
                    if (new String(Base64.getDecoder().decode(frame.asText()), StandardCharsets.UTF_8).contains(text)) {
                        return true;
                    }
                }
            }
        } catch (java.io.IOException | RuntimeException e) {
            // not written yet
        }
        return false;
    }
}
