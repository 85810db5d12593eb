package org.miron.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Endpoints;
import org.miron.testkit.runtime.GrootClient;

/** {@code miron execute TREE --groot PORT} as a real process: Groot2 is served, and SIGTERM ends a tree paused at a breakpoint. */
public class ExecuteGrootTest {
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();


    @Test
    public void executeServesGrootAndStopsWhilePausedAtABreakpoint() throws Exception {
        Path tree = tmp.getRoot().toPath().resolve("sleep.xml");
        Files.writeString(tree, "<root BTCPP_format=\"4\"><BehaviorTree ID=\"Main\"><Sequence>"
                + "<Script code=\"n := 1\"/><Sleep msec=\"60000\"/></Sequence></BehaviorTree></root>");
        Endpoints ep = Endpoints.freeLoopback();
        int port = GrootClient.freePortPair();
        Path out = tmp.getRoot().toPath().resolve("stdout.txt");
        Path err = tmp.getRoot().toPath().resolve("stderr.txt");
        Process p = new ProcessBuilder(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                CliProcess.classpath(), MironCli.class.getName(), "execute", tree.toString(), "--period", "20", "--groot",
                Integer.toString(port), "--request", ep.request(), "--bus-in", ep.busIn(), "--bus-out", ep.busOut(),
                "--skill-events", ep.skillEvents()))
                .redirectOutput(out.toFile()).redirectError(err.toFile()).start();
        try (GrootClient first = new GrootClient(port)) {
            assertNotNull("served: " + read(err), first.requestUntilAnswered('T', 30_000));
        }
        // A client of a server already bound: its subscriber connects at once. The first one connected
        // before the process bound, and reconnects on ZeroMQ's timer: a notice sent meanwhile is lost.
        try (GrootClient groot = new GrootClient(port)) {
            assertTrue("the notice subscriber reaches the publisher", groot.awaitSubscriber(10_000));
            List<byte[]> reply = groot.request('T');
            assertNotNull("served: " + read(err), reply);
            String xml = GrootClient.text(reply.get(1));
            assertTrue(xml, xml.contains("<Sleep name=\"Sleep\" _uid=\"3\" msec=\"60000\"/>"));
            // the Sleep runs: its hook is asked at the next tick, and the tree pauses there
            reply = groot.request('I', "{\"enabled\":true,\"uid\":3,\"mode\":0,\"once\":false,\"desired_status\":\"SKIPPED\",\"position\":0}");
            assertNotNull(reply);
            List<byte[]> notice = groot.awaitNotice(20_000);
            assertNotNull("breakpoint reached: " + read(out) + read(err), notice);
            assertEquals("3", GrootClient.text(notice.get(1)));
            p.destroy(); // SIGTERM while paused
            assertTrue("stops though paused: " + read(err), p.waitFor(20, TimeUnit.SECONDS));
            assertEquals(143, p.exitValue());
            assertTrue(read(out), read(out).contains("groot2: 127.0.0.1:" + port));
        } finally {
            p.destroyForcibly();
        }
    }

    private static String read(Path file) throws Exception {
        return Files.exists(file) ? Files.readString(file, StandardCharsets.UTF_8) : "";
    }
}
