package org.miron.cli.monitor;

import static org.junit.Assert.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.Assume;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Endpoints;
import org.miron.runtime.broker.Broker;
import org.miron.testkit.RepositoryRoot;
import org.miron.testkit.runtime.GrootClient;

/**
 * The live page debugs a tree on the real BehaviorTree.CPP 4 as it debugs one on ours: the monitor
 * attaches to the library's own Groot2Publisher ({@code miron-btcpp-run --groot}); a breakpoint set
 * by clicking pauses the tree (page, blackboard), continue and step go on, a forced FAILURE sends
 * the Fallback to its other branch (the runner's own trace says so). Skipped, saying why, without
 * Chromium or the runner (scripts/ensure-btcpp-plugin.sh builds it).
 */
public class DebugPageBtcppTest {
    private static final long TIMEOUT_MS = 60_000;
    private static final Path RUNNER = RepositoryRoot.path().resolve("build/miron-btcpp/miron-btcpp-run");

    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();

    @Test
    public void thePageDebugsBehaviorTreeCppsOwnPublisher() throws Exception {
        String chromium = HeadlessChromium.find().orElse(null);
        boolean built = Files.isExecutable(RUNNER);
        if (chromium == null || !built) {
            System.err.println("DebugPageBtcppTest: skipped, " + (chromium == null ? "no chromium on the PATH" : "no " + RUNNER));
        }
        Assume.assumeTrue(chromium != null && built);
        Path tree = tmp.getRoot().toPath().resolve("mission.xml");
        Files.writeString(tree, DebugPageBrowserTest.TREE);
        Path trace = tmp.getRoot().toPath().resolve("trace.jsonl");
        Endpoints ep = Endpoints.freeLoopback();
        int groot = GrootClient.freePortPair();
        try (HeadlessChromium browser = new HeadlessChromium(chromium, tmp.newFolder("profile").toPath());
                Broker broker = new Broker(ep).start();
                MonitorServer monitor = LiveMonitor.start(0, tree, ep, LiveMonitor.plainNames()).attachGroot(groot)) {
            Process runner = new ProcessBuilder(List.of(RUNNER.toString(), tree.toString(), "--trace", "--repeat", "--period",
                    "20", "--bus", ep.busOut(), "--skill-requests", ep.request(), "--skill-results", ep.skillEvents(),
                    "--groot", Integer.toString(groot))).redirectOutput(trace.toFile())
                    .redirectError(tmp.getRoot().toPath().resolve("stderr.txt").toFile()).start();
            try {
                browser.open(monitor.url());
                DebugPage page = new DebugPage(browser, TIMEOUT_MS);
                page.await(DebugPage.STATUS, s -> s.startsWith("running (attached to 127.0.0.1:" + groot), "attached");
                String mark = page.id("mark");
                String drive = page.id("drive");
                page.click(mark);
                page.run("document.getElementById('debug-break-pre').click()");
                page.await(DebugPage.STATUS, s -> s.equals("paused before mark (" + mark + ")"), "paused at mark");
                page.awaitTrue("!!document.querySelector('#blackboard tr[data-name=\"Main/mission_started\"]')", "the blackboard");
                long pauses = page.pauses();
                page.run("document.getElementById('debug-continue').click()");
                page.awaitTrue("debug.state.pauses>" + pauses, "a new pause after continue");
                page.await(DebugPage.STATUS, s -> s.equals("paused before mark (" + mark + ")"), "paused at mark again");
                pauses = page.pauses();
                page.run("document.getElementById('debug-step').click()");
                page.awaitTrue("debug.state.pauses>" + pauses, "a new pause after step");
                page.await(DebugPage.STATUS, s -> s.equals("paused before mission (0), stepping"), "paused before the root");
                page.click(mark);
                page.run("document.getElementById('debug-clear').click()");
                page.await("document.querySelector('#hooks').textContent", s -> !s.contains("mark"), "mark's breakpoint gone");
                page.run("document.getElementById('debug-continue').click()");
                page.await(DebugPage.STATUS, s -> s.startsWith("running"), "running again");
                page.click(drive);
                page.run("document.getElementById('debug-force-FAILURE').click()");
                page.awaitTrue("node('" + drive + "').classList.contains('forced')", "drive marked as forced");
                long end = System.currentTimeMillis() + TIMEOUT_MS;
                String backup = "\"node\":\"backup\",\"to\":\"RUNNING\"";
                while (System.currentTimeMillis() < end && !Files.readString(trace, StandardCharsets.UTF_8).contains(backup)) {
                    Thread.sleep(50);
                }
                assertTrue("BehaviorTree.CPP takes the other branch: " + Files.readString(trace),
                        Files.readString(trace).contains(backup));
            } finally {
                runner.destroy();
                if (!runner.waitFor(20, TimeUnit.SECONDS)) {
                    runner.destroyForcibly();
                }
            }
        }
    }
}
