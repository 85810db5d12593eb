package org.miron.cli.monitor;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BooleanSupplier;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.cli.MironCli;
import org.miron.testkit.RepositoryRoot;

import picocli.CommandLine;

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
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cli = MironCli.commandLine();
        cli.setOut(new PrintWriter(out, true));
        cli.setErr(new PrintWriter(err, true));
        AtomicInteger status = new AtomicInteger(-1);
        Thread demo = new Thread(() -> status.set(cli.execute("demo", "--model",
                RepositoryRoot.resolve("examples/hospital-delivery/hospital.miron").toString(), "--out",
                temp.getRoot().getPath(), "--time-scale", "0.4", "--monitor", "0")), "demo");
        demo.start();
        Pattern url = Pattern.compile("live monitor on (http://127\\.0\\.0\\.1:\\d+/)");
        await("the monitor's address", () -> url.matcher(out.toString()).find() || !demo.isAlive());
        Matcher found = url.matcher(out.toString());
        assertTrue(out + "\n" + err, found.find());
        String base = found.group(1);

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
        demo.join(TIMEOUT_MS);
        assertEquals(err.toString(), 0, status.get());
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
