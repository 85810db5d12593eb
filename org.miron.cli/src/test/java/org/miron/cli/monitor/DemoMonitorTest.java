package org.miron.cli.monitor;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.BooleanSupplier;
import java.util.stream.Stream;

import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * `miron demo --monitor 0` on the hospital example, watched with a real HTTP client while it runs:
 * the page holds the woven tree and its variant Switches, and the event stream carries node
 * statuses and the decision to charge first.
 */
public class DemoMonitorTest {
    private static final long TIMEOUT_MS = 120_000;

    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    @Test
    public void thePageFollowsTheDemo() throws Exception {
        MonitoredDemo demo = new MonitoredDemo(temp.getRoot().getPath(), "0.4");
        String base = demo.awaitUrl(TIMEOUT_MS);
        assertTrue(demo.printed(), base != null);

        HttpClient http = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(10)).build();
        String page = http.send(HttpRequest.newBuilder(URI.create(base)).build(), HttpResponse.BodyHandlers.ofString()).body();
        assertTrue(page.contains("data-id=\"0.1.1.0\""));
        assertTrue(page.contains("\"key\":\"preparation_sel\""));
        List<String> events = new CopyOnWriteArrayList<>();
        HttpResponse<Stream<String>> stream = http.send(HttpRequest.newBuilder(URI.create(base + "events")).build(),
                HttpResponse.BodyHandlers.ofLines());
        Thread reader = new Thread(() -> {
            try {
                stream.body().forEach(events::add);
            } catch (RuntimeException closed) {
                // the demo ended and took the server with it
            }
        }, "sse-reader");
        reader.setDaemon(true);
        reader.start();
        await("a running node", () -> events.stream().anyMatch(l -> l.startsWith("data: {") && l.contains("\"to\":\"RUNNING\"")));
        await("the decision to charge first", () -> events.stream().anyMatch(
                l -> l.contains("\"name\":\"preparation\"") && l.contains("\"value\":\"charge\"")));
        assertEquals(demo.errors(), 0, demo.await(TIMEOUT_MS));
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
