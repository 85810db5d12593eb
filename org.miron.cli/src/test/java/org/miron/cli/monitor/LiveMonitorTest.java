package org.miron.cli.monitor;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.BooleanSupplier;
import java.util.stream.Stream;

import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.executor.NodeStatus;
import org.miron.runtime.Endpoints;
import org.miron.runtime.Json;
import org.miron.runtime.broker.Broker;
import org.miron.runtime.bus.BusClient;
import org.miron.runtime.live.LiveExecutor;
import org.miron.runtime.skill.SkillInterfaceMock;
import org.miron.runtime.skill.SkillTable;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.NullNode;

/**
 * The live monitor with a real HTTP client against a real broker, skill interface and executors on
 * 127.0.0.1: the page holds the tree's nodes as the executor numbers them, the event stream carries
 * every status change, a second executor after the first one stopped is followed on the same
 * stream, varpoints and metrics arrive, and a malformed bus message is counted, not fatal.
 */
public class LiveMonitorTest {
    private static final long TIMEOUT_MS = 60_000;

    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    private final HttpClient http = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(10)).build();

    @Test
    public void followsExecutorsThroughRestarts() throws Exception {
        Path tree = temp.getRoot().toPath().resolve("tree.bt");
        Files.writeString(tree, """
                <root main_tree_to_execute="T">
                  <BehaviorTree ID="T">
                    <Sequence name="mission">
                      <Action ID="move" x="1"/>
                      <SubTreePlus ID="U" name="finish"/>
                    </Sequence>
                  </BehaviorTree>
                  <BehaviorTree ID="U"><Action ID="beep"/></BehaviorTree>
                </root>
                """);
        Endpoints endpoints = Endpoints.freeLoopback();
        SkillTable.Entry skill = new SkillTable.Entry(150, "SUCCESS", NullNode.getInstance(), Json.object());
        try (Broker broker = new Broker(endpoints).start();
                SkillInterfaceMock skills = new SkillInterfaceMock(endpoints.skill(), endpoints.skillEvents(),
                        new SkillTable(Map.of("*", skill))).start();
                MonitorServer monitor = LiveMonitor.start(0, tree, endpoints, LiveMonitor.plainNames());
                BusClient probe = new BusClient("probe", endpoints.busIn(), null, List.of(), (t, b) -> { }).start()) {
            String page = get(monitor, "/");
            for (String id : List.of("0", "0.0", "0.1", "0.1.0")) {
                assertTrue(id, page.contains("data-id=\"" + id + "\""));
            }
            assertTrue(page.contains("new EventSource('events')"));

            List<String> events = new CopyOnWriteArrayList<>();
            HttpResponse<Stream<String>> stream = http.send(HttpRequest.newBuilder(URI.create(monitor.url() + "events")).build(),
                    HttpResponse.BodyHandlers.ofLines());
            assertEquals(200, stream.statusCode());
            assertTrue(stream.headers().firstValue("Content-Type").orElse("").startsWith("text/event-stream"));
            Thread reader = new Thread(() -> stream.body().forEach(events::add), "sse-reader");
            reader.setDaemon(true);
            reader.start();
            await("snapshot", () -> events.contains("event: snapshot"));

            // The monitor hears the bus before any executor runs: a decision and a metric.
            probe.publish("miron.variant.task", "{\"varpoint\":\"task\",\"value\":\"dock\",\"seq\":1,\"time\":0}");
            probe.publish("roqme.estimate", "{\"name\":\"safety\",\"namespace\":\"X\",\"value\":0.35,\"time\":0}");
            await("varpoint and metric", () -> state(monitor).path("varpoints").path("task").asText().equals("dock")
                    && state(monitor).path("metrics").path("safety").asDouble() == 0.35);
            assertTrue(events.stream().anyMatch(l -> l.startsWith("data: {\"name\":\"task\"")));

            for (int run = 1; run <= 2; run++) {
                int from = events.size();
                try (LiveExecutor executor = new LiveExecutor(endpoints).build(tree, null)) {
                    assertEquals(NodeStatus.SUCCESS, executor.run(Duration.ofMillis(20)));
                }
                await("statuses of run " + run, () -> statuses(since(events, from)).containsAll(
                        List.of("0.0 RUNNING", "0.0 SUCCESS", "0.1.0 RUNNING", "0.1.0 SUCCESS", "0 SUCCESS")));
                assertTrue("run " + run + " announced its tree", since(events, from).contains("event: reset"));
            }
            assertEquals(1, monitor.connectedPages());

            probe.publish("miron.bt.status", "{not json");
            await("rejected", () -> state(monitor).path("rejected").asLong() >= 1);
            assertTrue(get(monitor, "/").contains("<svg"));
        }
    }

    private String get(MonitorServer monitor, String path) throws Exception {
        HttpResponse<String> response = http.send(HttpRequest.newBuilder(URI.create(monitor.url() + path.substring(1))).build(),
                HttpResponse.BodyHandlers.ofString());
        assertEquals(200, response.statusCode());
        return response.body();
    }

    private JsonNode state(MonitorServer monitor) {
        try {
            return Json.MAPPER.readTree(get(monitor, "/state"));
        } catch (Exception e) {
            throw new AssertionError(e);
        }
    }

    private static List<String> since(List<String> events, int from) {
        List<String> copy = new ArrayList<>(events);
        return copy.subList(Math.min(from, copy.size()), copy.size());
    }

    /** "node STATUS" of every status event in a list of stream lines. */
    private static List<String> statuses(List<String> lines) {
        List<String> result = new ArrayList<>();
        String event = null;
        for (String line : lines) {
            if (line.startsWith("event: ")) {
                event = line.substring(7);
            } else if (line.startsWith("data: ") && "status".equals(event)) {
                try {
                    JsonNode m = Json.MAPPER.readTree(line.substring(6));
                    result.add(m.path("node").asText() + " " + m.path("to").asText());
                } catch (Exception e) {
                    throw new AssertionError(line, e);
                }
            }
        }
        return result;
    }

    private static void await(String what, BooleanSupplier condition) throws InterruptedException {
        long end = System.currentTimeMillis() + TIMEOUT_MS;
        while (!condition.getAsBoolean()) {
            if (System.currentTimeMillis() > end) {
                throw new AssertionError("timed out waiting for " + what);
            }
            Thread.sleep(20);
        }
    }
}
