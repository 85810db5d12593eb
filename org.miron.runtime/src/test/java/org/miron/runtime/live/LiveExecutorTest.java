package org.miron.runtime.live;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.NullNode;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import org.junit.After;
import org.junit.Before;
import org.junit.Test;
import org.miron.executor.NodeStatus;
import org.miron.runtime.Endpoints;
import org.miron.runtime.Json;
import org.miron.runtime.broker.Broker;
import org.miron.runtime.bus.BusClient;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.skill.SkillInterfaceMock;
import org.miron.runtime.skill.SkillTable;
import org.miron.testkit.RepositoryRoot;
import org.miron.testkit.runtime.BusProbe;

/**
 * The woven intralogistics tree run by the live executor over real loopback sockets: a broker, the
 * mock skill interface, and decisions published on the bus as the engine would publish them.
 */
public class LiveExecutorTest {
    private static final Path WOVEN = RepositoryRoot.path()
            .resolve("org.miron.executor/src/test/resources/executor/intralogistics.ext.xml");

    private final Endpoints endpoints = Endpoints.freeLoopback();
    private Broker broker;
    private SkillInterfaceMock skills;
    private BusClient engine;
    private LiveExecutor executor;

    @Before
    public void start() {
        broker = new Broker(endpoints).start();
        SkillTable.Entry navigate = new SkillTable.Entry(1500, "SUCCESS", NullNode.getInstance(), Json.object());
        SkillTable.Entry handle = new SkillTable.Entry(50, "SUCCESS", NullNode.getInstance(), Json.object());
        skills = new SkillInterfaceMock(endpoints.skill(), endpoints.skillEvents(),
                new SkillTable(Map.of("navigate", navigate, "objectpick", handle, "objectdrop", handle))).start();
        engine = new BusClient("fake-engine", endpoints.busIn(), null, List.of(), (t, b) -> { }).start();
    }

    @After
    public void stop() {
        // A set-up that failed half-way must report its own cause, not a NullPointerException here.
        for (AutoCloseable part : new AutoCloseable[] { executor, engine, skills, broker }) {
            if (part != null) {
                try {
                    part.close();
                } catch (Exception e) {
                    throw new IllegalStateException(e);
                }
            }
        }
    }

    private void decide(String value) {
        engine.publish(Topics.VARIANT_PREFIX + "task",
                "{\"varpoint\":\"task\",\"value\":\"" + value + "\",\"seq\":1,\"time\":0}");
    }

    private CompletableFuture<NodeStatus> runExecutor() {
        executor = new LiveExecutor(endpoints).build(WOVEN, null);
        return CompletableFuture.supplyAsync(() -> executor.run(Duration.ofMillis(20)));
    }

    private JsonNode awaitPush(Predicate<JsonNode> p) throws InterruptedException {
        long end = System.currentTimeMillis() + 10_000;
        while (System.currentTimeMillis() < end) {
            for (JsonNode skill : skills.pushed()) {
                if (p.test(skill)) {
                    return skill;
                }
            }
            Thread.sleep(10);
        }
        return null;
    }

    private static boolean navigatesTo(JsonNode skill, double x, double y) {
        return skill.path("name").asText().equals("navigate") && skill.path("in-attribute").path("x").asDouble() == x
                && skill.path("in-attribute").path("y").asDouble() == y;
    }

    @Test
    public void dockDecisionHaltsTheMissionAndRunsCharge() throws Exception {
        CompletableFuture<NodeStatus> run = runExecutor();
        // No decision yet: the Switch runs its default, the nominal PickDeliverCharge, which goes to the shelf.
        assertNotNull("the nominal mission starts", awaitPush(s -> navigatesTo(s, -6.5, 1.25)));

        decide("dock"); // well within the 1.5 s of the first move, even on a loaded machine

        assertEquals(NodeStatus.SUCCESS, run.get(15, TimeUnit.SECONDS));
        assertTrue("the running skill was aborted",
                skills.results().stream().anyMatch(r -> r.path("result").path("result").asText().equals("ABORT")));
        List<JsonNode> pushed = skills.pushed();
        assertTrue(pushed.toString(), navigatesTo(pushed.get(pushed.size() - 1), -9.33, 2.17));
        assertTrue("no pick happened", pushed.stream().noneMatch(s -> s.path("name").asText().equals("objectpick")));
    }

    @Test
    public void theNominalIntralogisticsMissionRunsToCompletionAgainstTheSkillInterface() throws Exception {
        Path example = RepositoryRoot.path().resolve("examples/intralogistics/intralogistics.bt");
        executor = new LiveExecutor(endpoints).build(example, null);
        assertEquals(NodeStatus.SUCCESS, executor.run(Duration.ofMillis(5)));

        List<String> expected = new java.util.ArrayList<>();
        for (int delivery = 0; delivery < 3; delivery++) {
            expected.addAll(List.of("MoveTo -2.5 6.4", "objectpick", "MoveTo -8.08 4.11", "objectdrop"));
        }
        expected.add("MoveTo -9.33 2.17");
        List<String> pushed = new java.util.ArrayList<>();
        for (JsonNode skill : skills.pushed()) {
            JsonNode in = skill.path("in-attribute");
            pushed.add(skill.path("name").asText().equals("MoveTo")
                    ? "MoveTo " + in.path("x").asDouble() + " " + in.path("y").asDouble() : skill.path("name").asText());
        }
        assertEquals(expected, pushed);
    }

    @Test
    public void lateExecutorGetsTheCurrentDecisionFromTheCache() throws Exception {
        try (BusProbe probe = new BusProbe(endpoints.busOut(), Topics.VARIANT_PREFIX)) {
            decide("dock");
            assertNotNull(probe.await(Topics.VARIANT_PREFIX + "task", m -> true, 10_000));
        }
        CompletableFuture<NodeStatus> run = runExecutor();
        assertEquals(NodeStatus.SUCCESS, run.get(10, TimeUnit.SECONDS));
        List<JsonNode> pushed = skills.pushed();
        assertEquals(pushed.toString(), 1, pushed.size());
        assertTrue(pushed.toString(), navigatesTo(pushed.get(0), -9.33, 2.17));
    }
}
