package org.miron.cli.faults;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Endpoints;
import org.miron.runtime.Json;
import org.miron.runtime.broker.Broker;
import org.miron.runtime.skill.SkillInterfaceMock;
import org.miron.runtime.skill.SkillTable;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.NullNode;

/**
 * `miron execute TREE --monitor 0` as a process: it says where its page is, the page serves the
 * tree, and the state it shows follows the node statuses the executor publishes through the broker.
 */
public class ExecuteMonitorTest {
    private static final long TIMEOUT = 60_000;
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();
    private final Endpoints ep = Endpoints.freeLoopback();

    @Test
    public void pageFollowsTheRun() throws Exception {
        Path tree = tmp.getRoot().toPath().resolve("mission.bt");
        Files.writeString(tree, "<root main_tree_to_execute=\"Main\">\n  <BehaviorTree ID=\"Main\">\n"
                + "    <Repeat num_cycles=\"5\" name=\"rounds\">\n      <Sequence name=\"round\">\n"
                + "        <Action ID=\"Fetch\"/>\n        <Action ID=\"Deliver\"/>\n      </Sequence>\n    </Repeat>\n"
                + "  </BehaviorTree>\n</root>\n");
        SkillTable.Entry slow = new SkillTable.Entry(400, "SUCCESS", NullNode.getInstance(), Json.object());
        try (Broker broker = new Broker(ep).start();
                SkillInterfaceMock skills = new SkillInterfaceMock(ep.skill(), ep.skillEvents(),
                        new SkillTable(Map.of("*", slow))).start();
                RuntimeProcess execute = RuntimeProcess.start(tmp.getRoot().toPath(), "execute", "execute",
                        tree.toString(), "--period", "20", "--request", ep.request(), "--skill-events",
                        ep.skillEvents(), "--bus-in", ep.busIn(), "--bus-out", ep.busOut(), "--monitor", "0")) {
            assertTrue(execute.output(), execute.awaitOutput("live monitor: http://127.0.0.1:", TIMEOUT));
            Matcher url = Pattern.compile("live monitor: (http://127\\.0\\.0\\.1:\\d+/)").matcher(execute.output());
            assertTrue(execute.output(), url.find());
            HttpClient http = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(10)).build();
            String page = http.send(HttpRequest.newBuilder(URI.create(url.group(1))).build(),
                    HttpResponse.BodyHandlers.ofString()).body();
            assertTrue(page, page.contains("data-id=\"0.0.1\"") && page.contains(">Deliver<"));
            long end = System.currentTimeMillis() + TIMEOUT;
            boolean seen = false;
            while (!seen && System.currentTimeMillis() < end) {
                JsonNode state;
                try {
                    state = Json.MAPPER.readTree(http.send(HttpRequest.newBuilder(URI.create(url.group(1) + "state"))
                            .build(), HttpResponse.BodyHandlers.ofString()).body());
                } catch (java.io.IOException gone) {
                    break; // the run ended, and its page with it
                }
                seen = state.path("tree").asText().equals("Main") && state.path("statuses").has("0.0.1");
                Thread.sleep(20);
            }
            assertTrue("the page's state got the Deliver node's status\n" + execute.output(), seen);
            assertEquals(execute.output(), 0, execute.awaitExit(TIMEOUT));
            assertTrue(execute.output(), execute.output().contains("tree Main finished: SUCCESS"));
        }
    }
}
