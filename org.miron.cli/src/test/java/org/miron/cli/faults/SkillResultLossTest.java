package org.miron.cli.faults;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.node.NullNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.After;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.executor.NodeStatus;
import org.miron.executor.skills.SkillHandle;
import org.miron.executor.skills.SkillRequest;
import org.miron.executor.skills.SkillResult;
import org.miron.runtime.Endpoints;
import org.miron.runtime.Json;
import org.miron.runtime.broker.Broker;
import org.miron.runtime.live.LiveExecutor;
import org.miron.runtime.skill.SkillDeadlines;
import org.miron.runtime.skill.SkillInterfaceMock;
import org.miron.runtime.skill.SkillTable;
import org.miron.runtime.skill.ZmqSkillClient;

/**
 * Issue 10, item 4: a pushed skill whose result cannot come any more ends with ERROR instead of
 * keeping its node RUNNING: the skill interface process is killed (-9) and restarted while the
 * skill runs, or the result deadline passes.
 */
public class SkillResultLossTest {
    private static final long TIMEOUT = 30_000;
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();
    private final Endpoints ep = Endpoints.freeLoopback();
    private Broker broker;
    private RuntimeProcess skills;
    private ZmqSkillClient client;

    @After
    public void tearDown() throws Exception {
        for (AutoCloseable c : new AutoCloseable[] {client, skills, broker}) {
            if (c != null) {
                c.close();
            }
        }
    }

    private RuntimeProcess startSkills(Path table) throws Exception {
        RuntimeProcess p = RuntimeProcess.start(tmp.getRoot().toPath(), "skill-mock", "skill-mock", "--rep", ep.skill(),
                "--pub", ep.skillEvents(), "--skills", table.toString());
        assertTrue("skill interface up:\n" + p.output(), p.awaitOutput("skill interface mock: queries", TIMEOUT));
        return p;
    }

    @Test
    public void aSkillRunningWhenTheSkillInterfaceDiesFails() throws Exception {
        Path table = tmp.newFile("skills.json").toPath();
        Files.writeString(table, "{\"Wait\": {\"duration\": 600000, \"result\": \"SUCCESS\"}}");
        broker = new Broker(ep).start();
        skills = startSkills(table);
        client = new ZmqSkillClient(ep.request(), ep.skillEvents(), 1000).start();
        awaitResultsConnection();
        SkillHandle wait = client.pushSkill(new SkillRequest("Wait", Map.of()));
        long end = System.currentTimeMillis() + TIMEOUT;
        while (client.acknowledgedRunning() == 0 && System.currentTimeMillis() < end) {
            Thread.sleep(10);
        }
        assertEquals("the interface took the skill", 1, client.acknowledgedRunning());

        skills.kill();
        skills.close();
        skills = startSkills(table);
        SkillResult result = wait.result().get(TIMEOUT, TimeUnit.MILLISECONDS);
        assertEquals("a lost result is an error, not RUNNING forever", SkillResult.Outcome.ERROR, result.outcome());
        assertTrue(String.valueOf(result.value()), String.valueOf(result.value()).contains("went away"));

        // the restarted interface serves new pushes
        Files.writeString(table, "{\"Wait\": {\"duration\": 10, \"result\": \"SUCCESS\"}}");
        skills.kill();
        skills = startSkills(table);
        SkillResult next = null;
        for (int i = 0; i < 5 && next == null; i++) {
            // a push acked just before a reconnect may fail again; the tree would retry just so
            SkillResult r = client.pushSkill(new SkillRequest("Wait", Map.of())).result().get(TIMEOUT, TimeUnit.MILLISECONDS);
            next = r.outcome() == SkillResult.Outcome.SUCCESS ? r : null;
        }
        assertNotNull("skills run again after the restart", next);
    }

    /** Results are only seen once the SUB is connected: wait for a throwaway skill's result first. */
    private void awaitResultsConnection() throws Exception {
        CompletableFuture<SkillResult> probe = client.pushSkill(new SkillRequest("Probe", Map.of())).result();
        assertNotNull(probe.get(TIMEOUT, TimeUnit.MILLISECONDS));
    }

    @Test
    public void aTreeWhoseSkillMissesItsDeadlineFailsAndTheSkillIsAborted() throws Exception {
        broker = new Broker(ep).start();
        SkillTable table = new SkillTable(Map.of("Wait", new SkillTable.Entry(600_000, "SUCCESS", NullNode.getInstance(),
                Json.object())));
        try (SkillInterfaceMock mock = new SkillInterfaceMock(ep.skill(), ep.skillEvents(), table).start();
                LiveExecutor executor = new LiveExecutor(ep)) {
            Path tree = tmp.newFile("t.bt").toPath();
            Files.writeString(tree, "<?xml version=\"1.0\"?>\n<root>\n  <BehaviorTree ID=\"Only\">\n"
                    + "    <Sequence>\n      <Action ID=\"Wait\"/>\n    </Sequence>\n  </BehaviorTree>\n</root>\n");
            executor.skillDeadlines(new SkillDeadlines(Map.of("Wait", 1500L))).build(tree, null);
            CompletableFuture<NodeStatus> run = CompletableFuture.supplyAsync(() -> executor.run(Duration.ofMillis(20)));
            assertEquals("the tree fails at the deadline instead of running for 10 minutes", NodeStatus.FAILURE,
                    run.get(TIMEOUT, TimeUnit.MILLISECONDS));
            long end = System.currentTimeMillis() + TIMEOUT;
            while (mock.results().stream().noneMatch(r -> r.path("result").path("result").asText().equals("ABORT"))
                    && System.currentTimeMillis() < end) {
                Thread.sleep(10);
            }
            assertTrue("the skill was aborted on the interface: " + mock.results(), mock.results().stream()
                    .anyMatch(r -> r.path("result").path("result").asText().equals("ABORT")));
        }
    }
}
