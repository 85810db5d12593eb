package org.miron.runtime.skill;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.After;
import org.junit.Before;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Connect;
import org.miron.runtime.Endpoints;
import org.miron.runtime.Json;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;

/** The mock over its real sockets, with the original ComponentSkillInterface messages. */
public class SkillInterfaceMockTest {
    private static final int TIMEOUT = 10_000;
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();
    private final Endpoints ep = Endpoints.freeLoopback();
    private final ZContext ctx = new ZContext();
    private SkillInterfaceMock mock;
    private ZMQ.Socket req;
    private ZMQ.Socket results;

    @Before
    public void setUp() throws Exception {
        Path table = tmp.newFile("skills.json").toPath();
        Files.writeString(table, "{\"GoTo\": {\"duration\": 50, \"result\": \"SUCCESS\", \"result-value\": \"arrived\"},"
                + " \"Dock\": {\"duration\": 60000, \"result\": \"SUCCESS\"}, \"*\": {\"duration\": 10, \"result\": \"ERROR\"}}");
        mock = new SkillInterfaceMock(ep.skill(), ep.skillEvents(), SkillTable.load(table)).start();
        req = ctx.createSocket(SocketType.REQ);
        req.setReceiveTimeOut(TIMEOUT);
        req.setLinger(0);
        Connect.connect(req, ep.skill());
        results = ctx.createSocket(SocketType.SUB);
        results.setReceiveTimeOut(TIMEOUT);
        results.setLinger(0);
        results.subscribe(new byte[0]);
        Connect.connect(results, ep.skillEvents());
    }

    @After
    public void tearDown() {
        mock.close();
        ctx.close();
    }

    private void query(String json) {
        req.send(json);
        byte[] ack = req.recv();
        assertNotNull("ack", ack);
        assertArrayEquals("ack is an empty frame", new byte[0], ack);
    }

    @Test
    public void changeParameterIsTaggedCommittedAndKept() throws Exception {
        query("{\"id\":2,\"msg-type\":\"query\",\"query\":{\"type\":\"change-parameter\","
                + "\"ParameterSetRepository\":\"CommNavigationObjects\",\"ParameterSet\":\"CdlParameter\","
                + "\"Component\":\"SmartCdlServer\",\"Parameter\":\"transvel\",\"values\":{\"1\":83.5,\"2\":83.5}}}");
        List<ParameterChange> h = mock.history();
        assertEquals(1, h.size());
        ParameterChange c = h.get(0);
        assertEquals(2, c.id());
        assertEquals("COMMNAVIGATIONOBJECTS.CDLPARAMETER.TRANSVEL", c.tag());
        assertEquals(List.of("COMMNAVIGATIONOBJECTS.CDLPARAMETER.TRANSVEL 83.5 83.5", "COMMIT"), c.commands());
        assertEquals(83.5, c.value(), 0.0);
        assertEquals(83.5, mock.committed(c.tag()).get().path("2").asDouble(), 0.0);
    }

    /** Skill results are published only after the subscriber is connected: retry a short skill until one arrives. */
    private JsonNode firstResult() throws Exception {
        String r = results.recvStr();
        assertNotNull("skill-result published", r);
        return Json.MAPPER.readTree(r);
    }

    @Test
    public void pushSkillPublishesItsResult() throws Exception {
        JsonNode result = null;
        for (int id = 10; id < 40 && result == null; id++) {
            query("{\"id\":" + id + ",\"msg-type\":\"push-skill\",\"skill\":{\"name\":\"GoTo\","
                    + "\"skill-definition-fqn\":\"x\",\"in-attribute\":{\"x\":-9.33,\"y\":2.17},\"out-attribute\":{}}}");
            results.setReceiveTimeOut(500);
            String r = results.recvStr();
            result = r == null ? null : Json.MAPPER.readTree(r);
        }
        assertNotNull("skill-result published", result);
        assertEquals("skill-result", result.path("msg-type").asText());
        assertEquals("SUCCESS", result.path("result").path("result").asText());
        assertEquals("arrived", result.path("result").path("result-value").asText());
        assertTrue(result.path("outputs").isObject());
    }

    @Test
    public void abortEndsRunningSkillsWithAbort() throws Exception {
        awaitSubscriberConnected();
        query("{\"id\":7,\"msg-type\":\"push-skill\",\"skill\":{\"name\":\"Dock\"}}");
        query("{\"id\":8,\"msg-type\":\"query\",\"query\":{\"type\":\"abort-current-skill\"}}");
        JsonNode r = firstResult();
        assertEquals(7, r.path("id").asInt());
        assertEquals("ABORT", r.path("result").path("result").asText());
    }

    @Test
    public void unknownSkillUsesTheDefaultEntryAndGarbageIsAcked() throws Exception {
        awaitSubscriberConnected();
        query("not json at all");
        query("{\"id\":9,\"msg-type\":\"push-skill\",\"skill\":{\"name\":\"Fly\"}}");
        JsonNode r = firstResult();
        assertEquals(9, r.path("id").asInt());
        assertEquals("ERROR", r.path("result").path("result").asText());
        assertEquals(1, mock.malformedRequests());
    }

    /** Pushes short skills until one result arrives, so later results are not lost to the slow joiner. */
    private void awaitSubscriberConnected() throws Exception {
        results.setReceiveTimeOut(300);
        for (int i = 0; i < 50; i++) {
            query("{\"id\":-1,\"msg-type\":\"push-skill\",\"skill\":{\"name\":\"GoTo\"}}");
            if (results.recvStr() != null) {
                Thread.sleep(100); // let any other in-flight probe result arrive, then drain it
                while (results.recvStr(ZMQ.DONTWAIT) != null) {
                    // drained
                }
                results.setReceiveTimeOut(TIMEOUT);
                return;
            }
        }
        throw new AssertionError("skill result subscriber never connected");
    }
}
