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

import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Endpoints;
import org.miron.runtime.Json;
import org.miron.runtime.live.LiveExecutor;
import org.miron.testkit.runtime.GrootClient;

/**
 * Bad requests to the page's debugger get an HTTP error with a message, and the monitor goes on:
 * over real HTTP to a monitor attached to a real Groot2 server of a tree running in this JVM.
 */
public class DebugRoutesTest {
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();

    private final HttpClient http = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(10)).build();

    private HttpResponse<String> post(MonitorServer monitor, String action, String body) throws Exception {
        return http.send(HttpRequest.newBuilder(URI.create(monitor.url() + "debug/" + action))
                .POST(HttpRequest.BodyPublishers.ofString(body)).build(), HttpResponse.BodyHandlers.ofString());
    }

    private HttpResponse<String> get(MonitorServer monitor, String action) throws Exception {
        return http.send(HttpRequest.newBuilder(URI.create(monitor.url() + "debug/" + action)).GET().build(),
                HttpResponse.BodyHandlers.ofString());
    }

    private static void assertRefused(HttpResponse<String> reply, int status, String message) {
        assertEquals(reply.body(), status, reply.statusCode());
        assertTrue(reply.body(), reply.body().startsWith(message));
    }

    @Test
    public void badRequestsAreRefusedWithAMessage() throws Exception {
        Path tree = tmp.getRoot().toPath().resolve("wait.xml");
        Files.writeString(tree, "<root BTCPP_format=\"4\"><BehaviorTree ID=\"Main\"><Sequence name=\"main\">"
                + "<Script name=\"set\" code=\"n := 1\"/><Sleep name=\"wait\" msec=\"60000\"/></Sequence></BehaviorTree></root>");
        Endpoints ep = Endpoints.freeLoopback();
        int groot = GrootClient.freePortPair();
        try (LiveExecutor executor = new LiveExecutor(ep).build(tree, null).serveGroot(groot);
                MonitorServer monitor = LiveMonitor.start(0, tree, ep, LiveMonitor.plainNames()).attachGroot(groot);
                MonitorServer alone = LiveMonitor.start(0, tree, ep, LiveMonitor.plainNames())) {
            Thread robot = new Thread(() -> executor.run(Duration.ofMillis(20)), "robot");
            robot.start();
            long end = System.currentTimeMillis() + 30_000;
            while (!Json.MAPPER.readTree(get(monitor, "state").body()).path("attached").asBoolean()) {
                assertTrue("attached", System.currentTimeMillis() < end);
                Thread.sleep(50);
            }
            assertRefused(post(monitor, "breakpoint", "{not json"), 400, "the request body is not JSON");
            assertRefused(post(monitor, "breakpoint", "[1]"), 400, "the request body is a JSON object");
            assertRefused(post(monitor, "breakpoint", "{}"), 400, "\"node\" is missing");
            assertRefused(post(monitor, "breakpoint", "{\"node\":\"7.7\"}"), 404, "unknown node 7.7");
            assertRefused(post(monitor, "breakpoint", "{\"node\":\"0.1\",\"position\":\"MIDDLE\"}"), 400,
                    "\"position\" is PRE or POST");
            assertRefused(post(monitor, "force", "{\"node\":\"0.1\",\"status\":\"RUNNING\"}"), 400,
                    "a forced result is SUCCESS, FAILURE or SKIPPED");
            assertRefused(post(monitor, "continue", ""), 409, "the tree is not paused");
            assertRefused(post(monitor, "clear", "{\"node\":\"0.1\"}"), 409, "no breakpoint or forced result on wait");
            assertRefused(post(monitor, "jump", "{}"), 404, "no such request");
            assertRefused(get(monitor, "step"), 405, "POST /debug/step");
            assertRefused(post(monitor, "breakpoint", "{\"node\":\"0.1\",\"pad\":\"" + "x".repeat(5000) + "\"}"), 400,
                    "a request body has at most");
            assertRefused(post(alone, "step", ""), 503, "no Groot2 server to debug with");
            // and the debugger still works: a forced SUCCESS ends the wait, the tree finishes
            assertEquals(200, post(monitor, "force", "{\"node\":\"0.1\",\"status\":\"SUCCESS\",\"once\":true}").statusCode());
            robot.join(30_000);
            assertTrue("the forced SUCCESS ended the minute's wait", !robot.isAlive());
        }
    }

    @Test
    public void aTreePausedByAPageThatWentAwayGoesOnAfterTheServersHeartbeat() throws Exception {
        Path tree = tmp.getRoot().toPath().resolve("after.xml");
        Files.writeString(tree, "<root BTCPP_format=\"4\"><BehaviorTree ID=\"Main\"><Sequence name=\"main\">"
                + "<Sleep name=\"first\" msec=\"200\"/><Script name=\"after\" code=\"m := 2\"/><Sleep name=\"wait\" msec=\"60000\"/>"
                + "</Sequence></BehaviorTree></root>");
        Endpoints ep = Endpoints.freeLoopback();
        int groot = GrootClient.freePortPair();
        java.util.concurrent.CountDownLatch afterDone = new java.util.concurrent.CountDownLatch(1);
        try (LiveExecutor executor = new LiveExecutor(ep).build(tree, (time, node, from, to) -> {
            if (node.name().equals("after") && to == org.miron.executor.NodeStatus.SUCCESS) {
                afterDone.countDown();
            }
        }).serveGroot(groot); MonitorServer monitor = LiveMonitor.start(0, tree, ep, LiveMonitor.plainNames()).attachGroot(groot)) {
            long end = System.currentTimeMillis() + 30_000;
            while (!Json.MAPPER.readTree(get(monitor, "state").body()).path("attached").asBoolean()) {
                assertTrue("attached", System.currentTimeMillis() < end);
                Thread.sleep(50);
            }
            assertEquals(200, post(monitor, "breakpoint", "{\"node\":\"0.1\"}").statusCode());
            Thread robot = new Thread(() -> executor.run(Duration.ofMillis(20)), "robot");
            robot.setDaemon(true);
            robot.start();
            while (Json.MAPPER.readTree(get(monitor, "state").body()).path("paused").isNull()) {
                assertTrue("paused at after", System.currentTimeMillis() < end);
                Thread.sleep(50);
            }
            // nobody asks any more: the monitor stops polling, the server's heartbeat frees the tree
            assertTrue("the tree goes on without a page", afterDone.await(30, java.util.concurrent.TimeUnit.SECONDS));
            executor.stop();
        }
    }
}
