package org.miron.cli.monitor;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.function.Predicate;
import org.junit.Assume;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.cli.MironCli;
import org.miron.executor.NodeStatus;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.recording.BtlogReader;
import org.miron.runtime.recording.BusLogReader;
import org.miron.runtime.recording.RecordedTree;
import org.miron.runtime.recording.Recording;
import org.miron.testkit.RepositoryRoot;
import picocli.CommandLine;

/**
 * A recorded demo replayed in headless Chromium: `miron demo --record` runs the hospital example,
 * the replay page is served over its recording, and the slider is moved to the adaptation that
 * decides to charge first and to an instant before it. At each, the page shows the nodes the
 * recording had RUNNING then (worked out here from the raw transitions) and the last decision by
 * then (from the bus log). Skipped, saying so, where no Chromium is installed.
 */
public class ReplayBrowserTest {
    private static final long TIMEOUT_MS = 60_000;

    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    @Test
    public void theSliderShowsTheRecordedStatusesAndDecisionAtThatInstant() throws Exception {
        String chromium = HeadlessChromium.find().orElse(null);
        if (chromium == null) {
            System.err.println("ReplayBrowserTest: skipped, no chromium on the PATH (apt-get install chromium)");
        }
        Assume.assumeNotNull(chromium);
        Path btlog = temp.getRoot().toPath().resolve("hospital.btlog");
        CommandLine cli = MironCli.commandLine();
        StringWriter out = new StringWriter();
        cli.setOut(new PrintWriter(out, true));
        cli.setErr(new PrintWriter(out, true));
        int status = cli.execute("demo", "--model", RepositoryRoot.resolve("examples/hospital-delivery/hospital.miron").toString(),
                "--out", temp.newFolder("demo").getPath(), "--time-scale", "0.5", "--record", btlog.toString());
        assertEquals(out.toString(), 0, status);

        Recording recording = BtlogReader.read(btlog);
        RecordedTree tree = RecordedTree.parse(recording.treeXml());
        List<BusLogReader.BusEvent> bus = BusLogReader.read(btlog.resolveSibling("hospital.bus.jsonl"));
        BusLogReader.BusEvent charge = bus.stream().filter(e -> e.topic().equals(Topics.DECISION)
                && e.message().path("decisions").path("preparation").asText().equals("charge")
                && e.message().path("changed").toString().contains("preparation")).findFirst()
                .orElseThrow(() -> new AssertionError("no decision to charge first in the bus log: " + out));
        long chargeAt = (charge.timeUs() - recording.startMicros() + 999) / 1000; // the first millisecond after it
        long before = Math.max(0, chargeAt - 1500);

        ReplayState replay = new ReplayState(recording, tree, bus, ReplayMonitor.plainNames());
        try (HeadlessChromium browser = new HeadlessChromium(chromium, temp.newFolder("profile").toPath());
                ReplayServer server = ReplayMonitor.start(0, "replay", tree, replay)) {
            browser.open(server.url());
            await(browser, "the page's event stream", "document.getElementById('connection').className", v -> v.equals("on"));
            JsonNode marks = browser.evaluate("Array.from(document.querySelectorAll('button.replay-mark')).map(b=>b.dataset.at).join(',')");
            assertTrue("the adaptation to charge first is a mark: " + marks, List.of(marks.asText().split(",")).contains(Long.toString(chargeAt)));

            for (long at : new long[] { chargeAt, before }) {
                browser.evaluate("(()=>{const s=document.getElementById('replay-time');s.value=" + at
                        + ";s.dispatchEvent(new Event('input'));return true;})()");
                String running = String.join(",", runningAt(recording, tree, at));
                await(browser, "the nodes running at " + at + " ms (" + running + ")",
                        "Array.from(document.querySelectorAll('#tree g.status-running')).map(g=>g.dataset.id).sort().join(',')",
                        v -> v.equals(running));
                long seq = lastDecisionSeq(bus, recording.startMicros(), at);
                assertTrue(at != chargeAt || seq >= charge.message().path("seq").asLong());
                await(browser, "decision #" + seq + " at " + at + " ms", "document.getElementById('replay-decision').dataset.seq||''",
                        v -> v.equals(seq < 0 ? "" : Long.toString(seq)));
                String preparation = preparationAt(bus, recording.startMicros(), at);
                assertTrue(at != chargeAt || preparation.equals("charge"));
                await(browser, "preparation = " + preparation + " at " + at + " ms",
                        "(document.querySelector('#varpoints tr[data-name=\"preparation\"] td')||{}).textContent||''",
                        v -> v.equals(preparation));
            }
        }
    }

    /** The page ids of the nodes whose last transition by {@code atMillis} is RUNNING, sorted as the page's are. */
    private static TreeSet<String> runningAt(Recording recording, RecordedTree tree, long atMillis) {
        Map<Integer, NodeStatus> last = new TreeMap<>();
        for (Recording.Transition t : recording.transitions()) {
            if (t.micros() <= atMillis * 1000) {
                last.put(t.uid(), t.status());
            }
        }
        TreeSet<String> running = new TreeSet<>();
        last.forEach((uid, s) -> {
            if (s == NodeStatus.RUNNING) {
                running.add(tree.node(uid).path());
            }
        });
        return running;
    }

    private static long lastDecisionSeq(List<BusLogReader.BusEvent> bus, long startMicros, long atMillis) {
        long seq = -1;
        for (BusLogReader.BusEvent e : bus) {
            if (e.topic().equals(Topics.DECISION) && e.timeUs() - startMicros <= atMillis * 1000) {
                seq = e.message().path("seq").asLong();
            }
        }
        return seq;
    }

    /** The last value of varpoint preparation by then, from the decisions and the variant messages ("" before any). */
    private static String preparationAt(List<BusLogReader.BusEvent> bus, long startMicros, long atMillis) {
        String value = "";
        for (BusLogReader.BusEvent e : bus) {
            if (e.timeUs() - startMicros > atMillis * 1000) {
                break;
            }
            if (e.topic().equals(Topics.DECISION) && e.message().path("decisions").has("preparation")) {
                value = e.message().path("decisions").path("preparation").asText();
            } else if (e.topic().equals(Topics.VARIANT_PREFIX + "preparation")) {
                value = e.message().path("value").asText();
            }
        }
        return value;
    }

    private static void await(HeadlessChromium browser, String what, String expression, Predicate<String> p) throws Exception {
        long end = System.currentTimeMillis() + TIMEOUT_MS;
        String seen = null;
        while (System.currentTimeMillis() < end) {
            JsonNode value = browser.evaluate(expression);
            seen = value == null ? null : value.asText();
            if (seen != null && p.test(seen)) {
                return;
            }
            Thread.sleep(50);
        }
        throw new AssertionError("the page did not show " + what + "; it shows: " + seen);
    }
}
