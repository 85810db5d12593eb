package org.miron.testkit.runtime;

import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.function.Predicate;
import org.miron.runtime.Endpoints;
import org.miron.runtime.broker.Broker;
import org.miron.runtime.bus.BusClient;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.engine.Engine;
import org.miron.runtime.engine.EngineOptions;
import org.miron.runtime.engine.EngineStartException;
import org.miron.runtime.skill.SkillInterfaceMock;
import org.miron.runtime.skill.SkillTable;

/**
 * Broker, skill interface mock, a bus probe, a test publisher and an engine on the test model
 * (copied to {@code dir} so a test may corrupt it), all on fresh loopback ports.
 */
public final class EngineFixture implements AutoCloseable {
    public static final long TIMEOUT = 20_000;
    public final Endpoints endpoints = Endpoints.freeLoopback();
    public final Path dir;
    public final Path ioJson;
    public final Path mzn;
    public Broker broker;
    public SkillInterfaceMock skills;
    public BusProbe probe;
    public BusClient input;
    public Engine engine;

    public EngineFixture(Path dir) throws IOException {
        this(dir, "testbot");
    }

    /** @param model one of {@link TestModels}: testbot or portbot */
    public EngineFixture(Path dir, String model) throws IOException {
        this.dir = dir;
        ioJson = TestModels.copy(model, dir);
        mzn = dir.resolve(model + ".mzn");
    }

    public EngineOptions options() {
        EngineOptions o = new EngineOptions(ioJson).endpoints(endpoints);
        o.timeLimitMs = 5000;
        o.decisionLog = dir.resolve("decisions.jsonl");
        o.ackTimeoutMs = 500;
        o.backoffMinMs = 100;
        o.backoffMaxMs = 400;
        o.statusIntervalMs = 1000;
        return o;
    }

    /** Broker, probe and input publisher; the skill mock and the engine are started separately. */
    public EngineFixture startInfrastructure() throws InterruptedException {
        broker = new Broker(endpoints).start();
        probe = new BusProbe(endpoints.busOut(), "miron.");
        input = new BusClient("test-input", endpoints.busIn(), null, List.of(), (t, b) -> { }).start();
        assertTrue("test publisher reaches the broker", input.awaitReady(TIMEOUT));
        return this;
    }

    public EngineFixture startSkills() {
        skills = new SkillInterfaceMock(endpoints.skill(), endpoints.skillEvents(), SkillTable.defaults()).start();
        return this;
    }

    public EngineFixture startEngine(EngineOptions o) throws EngineStartException {
        engine = Engine.create(o).start();
        return this;
    }

    /** Everything, then waits for the initial decision. */
    public EngineFixture startAll() throws Exception {
        startInfrastructure();
        startSkills();
        startEngine(options());
        assertNotNull("initial task decision", awaitVariant("task", "pickDeliverCharge"));
        syncInputs();
        return this;
    }

    /**
     * Makes sure the engine's input subscription is live: a neutral context (a known, full battery)
     * must cause one more solve. It arrives live or, if the engine's SUB connected late, through
     * the broker's last-value cache; either way later test messages then arrive live.
     */
    public void syncInputs() throws InterruptedException {
        long before = engine.status().get("solves");
        publish(Topics.CONTEXT, "{\"name\":\"BatteryLevel\",\"namespace\":\"Intralogistics\",\"type\":\"number\",\"value\":50}");
        long end = System.currentTimeMillis() + TIMEOUT;
        while (engine.status().get("solves") <= before && System.currentTimeMillis() < end) {
            Thread.sleep(10);
        }
        assertTrue("engine receives inputs", engine.status().get("solves") > before);
    }

    public JsonNode awaitVariant(String vp, String value) throws InterruptedException {
        return probe.await(Topics.VARIANT_PREFIX + vp, b -> value.equals(b.path("value").asText()), TIMEOUT);
    }

    public JsonNode awaitStatus(Predicate<JsonNode> p) throws InterruptedException {
        return probe.await(Topics.STATUS, p, TIMEOUT);
    }

    public void estimate(String name, double value) {
        input.publish(Topics.ESTIMATE, "{\"name\":\"" + name + "\",\"namespace\":\"Intralogistics\",\"value\":" + value
                + ",\"time\":" + System.currentTimeMillis() + "}");
    }

    public void publish(String topic, String body) {
        input.publish(topic, body);
    }

    @Override
    public void close() {
        for (AutoCloseable c : new AutoCloseable[] {engine, skills, input, probe, broker}) {
            if (c != null) {
                try {
                    c.close();
                } catch (Exception ignored) {
                    // best effort
                }
            }
        }
    }
}
