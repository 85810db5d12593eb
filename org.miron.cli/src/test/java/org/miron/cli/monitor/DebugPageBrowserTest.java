package org.miron.cli.monitor;

import org.miron.cli.CliProcess;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.Assume;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.cli.MironCli;
import org.miron.runtime.Endpoints;
import org.miron.runtime.FreePorts;
import org.miron.runtime.broker.Broker;
import org.miron.runtime.bus.Topics;
import org.miron.testkit.runtime.BusProbe;
import org.miron.testkit.runtime.GrootClient;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;

import com.fasterxml.jackson.databind.JsonNode;


/**
 * The live page's debugger in headless Chromium over a real `miron execute --repeat --monitor M
 * --groot G` process on a real bus: a breakpoint set by clicking a node pauses the tree (the page
 * says so, the node is marked, the blackboards are shown), continue lets it go, step pauses before
 * the root's next tick, a forced FAILURE sends the Fallback to its other branch (on the page and on
 * the bus); search and fold; an unknown node is refused on the page; and a monitor attached to
 * another process's Groot2 server shows "detached" when that executor goes away, and attaches again
 * when one comes back. Skipped, saying so, where no Chromium is installed.
 */
public class DebugPageBrowserTest {
    private static final long TIMEOUT_MS = 60_000;
    /**
     * mission: start, then primary (mark, drive 300 ms) or, if it fails, a variant Switch over
     * {route_sel}, unset: its default, backup (a minute).
     */
    static final String TREE = """
            <root BTCPP_format="4" main_tree_to_execute="Main">
              <BehaviorTree ID="Main">
                <Sequence name="mission">
                  <Script name="start" code="mission_started := true"/>
                  <Fallback name="choose">
                    <SubTree ID="Primary" name="primary"/>
                    <Switch2 name="route_switch" variable="{route_sel}" case_1="left" case_2="right">
                      <Sleep name="left_way" msec="60000"/>
                      <Sleep name="right_way" msec="60000"/>
                      <Sleep name="backup" msec="60000"/>
                    </Switch2>
                  </Fallback>
                </Sequence>
              </BehaviorTree>
              <BehaviorTree ID="Primary">
                <Sequence name="primary_steps">
                  <Script name="mark" code="route := 'primary'"/>
                  <Sleep name="drive" msec="300"/>
                </Sequence>
              </BehaviorTree>
            </root>
            """;
    private static final String STATUS = DebugPage.STATUS;
    private static final String MESSAGE = DebugPage.MESSAGE;
    /** The tree of the tests, also run on BehaviorTree.CPP by DebugPageBtcppTest. */

    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();

    private static String chromium() {
        String chromium = HeadlessChromium.find().orElse(null);
        if (chromium == null) {
            System.err.println("DebugPageBrowserTest: skipped, no chromium on the PATH (apt-get install chromium)");
        }
        Assume.assumeNotNull(chromium);
        return chromium;
    }

    @Test
    public void breakpointsStepsAndForcedResultsFromThePage() throws Exception {
        String chromium = chromium();
        try (HeadlessChromium browser = new HeadlessChromium(chromium, tmp.newFolder("profile").toPath())) {
            Endpoints ep = Endpoints.freeLoopback();
            int groot = GrootClient.freePortPair();
            int monitor = FreePorts.take(1)[0];
            try (Broker broker = new Broker(ep).start(); BusProbe bus = new BusProbe(ep.busOut(), Topics.BT_STATUS)) {
                Executor executor = new Executor(ep, "--monitor", Integer.toString(monitor), "--groot", Integer.toString(groot));
                try {
                    browser.open(executor.awaitMonitorUrl());
                    DebugPage page = new DebugPage(browser, TIMEOUT_MS);
                    page.await(STATUS, s -> s.startsWith("running (attached"), "attached");
                    String mark = page.id("mark");
                    String drive = page.id("drive");

                    // a breakpoint before mark, set by clicking the node then the button
                    page.click(mark);
                    page.run("document.getElementById('debug-break-pre').click()");
                    page.await(STATUS, s -> s.equals("paused before mark (" + mark + ")"), "paused at mark");
                    page.awaitTrue("node('" + mark + "').classList.contains('paused')", "mark marked as paused");
                    page.awaitTrue("node('" + mark + "').classList.contains('breakpoint')", "mark marked with a breakpoint");
                    page.await("document.querySelector('#blackboard tr[data-name=\"primary/route\"] td').textContent",
                            s -> s.equals("primary"), "the subtree's blackboard");
                    page.awaitTrue("!!document.querySelector('#blackboard tr[data-name=\"Main/mission_started\"]')",
                            "the main tree's blackboard");
                    browser.screenshot(Path.of("build", "screenshots", "live-debug.png")); // docs/images/live-debug.png is a copy

                    // continue: the tree goes on (drive runs, on the bus), and pauses at mark again next mission
                    long before = lastSeq(bus);
                    long pauses = page.pauses();
                    page.run("document.getElementById('debug-continue').click()");
                    assertNotNull("drive runs after continue", bus.await(Topics.BT_STATUS,
                            m -> m.path("seq").asLong() > before && m.path("node").asText().equals(drive)
                                    && m.path("to").asText().equals("RUNNING"), TIMEOUT_MS));
                    page.awaitTrue("debug.state.pauses>" + pauses, "a new pause");
                    page.await(STATUS, s -> s.equals("paused before mark (" + mark + ")"), "paused at mark again");

                    // step: the tick under way ends (mark succeeds, drive runs), and the tree pauses before the root
                    long beforeStep = lastSeq(bus);
                    long pausesBeforeStep = page.pauses();
                    page.run("document.getElementById('debug-step').click()");
                    page.awaitTrue("debug.state.pauses>" + pausesBeforeStep, "a new pause");
                    page.await(STATUS, s -> s.equals("paused before mission (0), stepping"), "paused before the root");
                    assertNotNull("mark ticked during the step", bus.await(Topics.BT_STATUS, m -> m.path("seq").asLong() > beforeStep
                            && m.path("node").asText().equals(mark) && m.path("to").asText().equals("SUCCESS"), TIMEOUT_MS));
                    page.await("Array.from(document.querySelectorAll('#hooks td')).map(td=>td.textContent).join(',')",
                            s -> s.contains("mission,step,always"), "the step's breakpoint listed");

                    // mark's breakpoint cleared, the step continued, drive forced to FAILURE: the Fallback takes backup
                    page.click(mark);
                    page.run("document.getElementById('debug-clear').click()");
                    page.await("document.querySelector('#hooks').textContent", s -> !s.contains("mark"), "mark's breakpoint gone");
                    page.run("document.getElementById('debug-continue').click()");
                    page.await(STATUS, s -> s.startsWith("running"), "running again");
                    page.click(drive);
                    page.run("document.getElementById('debug-force-FAILURE').click()");
                    String backup = page.id("backup");
                    assertNotNull("backup runs on the bus", bus.await(Topics.BT_STATUS,
                            m -> m.path("node").asText().equals(backup) && m.path("to").asText().equals("RUNNING"), TIMEOUT_MS));
                    page.awaitTrue("node('" + backup + "').classList.contains('status-running')", "backup running on the page");
                    page.awaitTrue("node('" + drive + "').classList.contains('forced')", "drive marked as forced");
                    assertNotNull("drive failed on the bus", bus.await(Topics.BT_STATUS,
                            m -> m.path("node").asText().equals(drive) && m.path("to").asText().equals("FAILURE"), TIMEOUT_MS));

                    // the variant Switch shows the decision that chose its branch, and why
                    String why = "{\"seq\":1,\"decisions\":{\"route\":\"left\"},\"changed\":[\"route\"],"
                            + "\"why\":{\"route\":{\"because\":\"rule blocked (corridor = BLOCKED)\",\"rules\":[\"blocked\"]}}}";
                    page.click(page.id("route_switch"));
                    try (ZContext zmq = new ZContext(); ZMQ.Socket pub = zmq.createSocket(SocketType.PUB)) {
                        pub.connect(ep.busIn());
                        String shown = "document.getElementById('debug-switch').textContent";
                        long end = System.currentTimeMillis() + TIMEOUT_MS;
                        JsonNode text = null;
                        while (System.currentTimeMillis() < end && (text == null || !text.asText().contains("blocked"))) {
                            pub.sendMore(Topics.DECISION); // again until it shows: a PUB drops what goes before the subscription
                            pub.send(why);
                            Thread.sleep(100);
                            text = browser.evaluate(shown);
                        }
                        assertEquals("variant switch of route = left: rule blocked (corridor = BLOCKED)", text.asText());
                    }

                    // search and fold
                    page.run("const s=document.getElementById('search');s.value='DRIV';s.dispatchEvent(new Event('input'))");
                    page.await("document.getElementById('search-count').textContent", s -> s.equals("1 found"), "search");
                    page.awaitTrue("node('" + drive + "').classList.contains('match')", "drive matched");
                    String primary = page.id("primary");
                    page.click(primary);
                    page.run("document.getElementById('debug-fold').click()");
                    page.awaitTrue("getComputedStyle(node('" + drive + "')).display==='none'"
                            + "&&getComputedStyle(node('" + mark + "')).display==='none'"
                            + "&&getComputedStyle(node('" + primary + "')).display!=='none'", "primary's children hidden");
                    page.run("document.getElementById('debug-fold').click()");
                    page.awaitTrue("getComputedStyle(node('" + drive + "')).display!=='none'", "unfolded");

                    // an unknown node is refused, with a message on the page
                    page.run("debugRequest('breakpoint',{node:'9.9.9',position:'PRE'})");
                    page.await(MESSAGE, s -> s.startsWith("unknown node 9.9.9"), "refused");
                } finally {
                    executor.stop();
                }
            }
        }
    }

    @Test
    public void aMonitorShowsDetachedWhenTheExecutorGoesAndAttachesWhenOneComes() throws Exception {
        String chromium = chromium();
        try (HeadlessChromium browser = new HeadlessChromium(chromium, tmp.newFolder("profile").toPath())) {
            Endpoints ep = Endpoints.freeLoopback();
            int groot = GrootClient.freePortPair();
            Path tree = treeFile();
            try (Broker broker = new Broker(ep).start();
                    MonitorServer monitor = LiveMonitor.start(0, tree, ep, LiveMonitor.plainNames()).attachGroot(groot)) {
                browser.open(monitor.url());
                DebugPage page = new DebugPage(browser, TIMEOUT_MS);
                page.await(STATUS, s -> s.startsWith("detached"), "detached before any executor");
                Executor first = new Executor(ep, "--groot", Integer.toString(groot));
                try {
                    page.await(STATUS, s -> s.startsWith("running (attached to 127.0.0.1:" + groot), "attached");
                } finally {
                    first.stop();
                }
                page.await(STATUS, s -> s.startsWith("detached: no answer from the Groot2 server at 127.0.0.1:" + groot),
                        "detached once the executor is gone");
                page.run("debugRequest('step')");
                page.await(MESSAGE, s -> s.startsWith("detached"), "a request while detached is refused");
                Executor second = new Executor(ep, "--groot", Integer.toString(groot));
                try {
                    page.await(STATUS, s -> s.startsWith("running (attached"), "attached to the new executor");
                } finally {
                    second.stop();
                }
            }
        }
    }

    private Path treeFile() throws Exception {
        Path tree = tmp.getRoot().toPath().resolve("mission.xml");
        if (!Files.exists(tree)) {
            Files.writeString(tree, TREE);
        }
        return tree;
    }

    private static long lastSeq(BusProbe bus) {
        return bus.messages(Topics.BT_STATUS).stream().mapToLong(m -> m.body() == null ? 0 : m.body().path("seq").asLong())
                .max().orElse(0);
    }

    /** `miron execute TREE --repeat --period 20 ...` as a real process on the test's bus. */
    private final class Executor {
        private final Process process;
        private final Path out;
        private final Path err;

        Executor(Endpoints ep, String... options) throws Exception {
            Path logs = Files.createDirectories(Path.of("build", "debug-page")); // kept for a failure's post-mortem
            out = Files.createTempFile(logs, "execute", ".out");
            err = Files.createTempFile(logs, "execute", ".err");
            List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                    "-cp", CliProcess.classpath(), MironCli.class.getName(), "execute", treeFile().toString(), "--repeat", "--period", "20",
                    "--request", ep.request(), "--bus-in", ep.busIn(), "--bus-out", ep.busOut(), "--skill-events", ep.skillEvents()));
            command.addAll(List.of(options));
            process = new ProcessBuilder(command).redirectOutput(out.toFile()).redirectError(err.toFile()).start();
        }

        String awaitMonitorUrl() throws Exception {
            Pattern url = Pattern.compile("live monitor: (http://127\\.0\\.0\\.1:\\d+/)");
            long end = System.currentTimeMillis() + TIMEOUT_MS;
            while (System.currentTimeMillis() < end && process.isAlive()) {
                Matcher m = url.matcher(Files.readString(out, StandardCharsets.UTF_8));
                if (m.find()) {
                    return m.group(1);
                }
                Thread.sleep(50);
            }
            throw new AssertionError("no monitor: " + Files.readString(out) + Files.readString(err));
        }

        void stop() throws Exception {
            process.destroy();
            if (!process.waitFor(20, TimeUnit.SECONDS)) {
                process.destroyForcibly();
            }
            assertEquals("stopped by SIGTERM: " + Files.readString(err), 143, process.exitValue());
        }
    }

}
