package org.miron.runtime.faults;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.After;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Connect;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.engine.IoModel;
import org.miron.runtime.player.Scenario;
import org.miron.runtime.skill.SkillTable;
import org.miron.testkit.runtime.EngineFixture;
import org.zeromq.SocketType;
import org.zeromq.ZContext;
import org.zeromq.ZMQ;

/** Issue 10, item 6: a JSON value followed by garbage is malformed everywhere JSON is read. */
public class TrailingTokensTest {
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();
    private EngineFixture f;

    @After
    public void tearDown() {
        if (f != null) {
            f.close();
        }
    }

    @Test
    public void estimateWithTrailingGarbageIsCountedAsMalformedAndIgnored() throws Exception {
        f = new EngineFixture(tmp.getRoot().toPath());
        f.startAll();
        f.publish(Topics.ESTIMATE, "{\"name\":\"power_autonomy\",\"namespace\":\"Intralogistics\",\"value\":0.2}xyz");
        assertNotNull("counted as malformed", f.awaitStatus(s -> s.path("counters").path("malformedInput").asLong() == 1));
        // a later valid input still solves, and the robot did not dock on the garbage
        f.estimate("safety", 0.2);
        assertNotNull(f.probe.await(Topics.DECISION, d -> d.path("decisions").path("maxVelocity").asInt() == 28,
                EngineFixture.TIMEOUT));
        assertTrue("the garbage estimate never reached the solver", f.probe.messages(Topics.VARIANT_PREFIX + "task")
                .stream().allMatch(m -> m.body().path("value").asText().equals("pickDeliverCharge")));
    }

    @Test
    public void skillRequestWithTrailingGarbageIsCountedAndAcked() throws Exception {
        f = new EngineFixture(tmp.getRoot().toPath());
        f.startSkills();
        try (ZContext ctx = new ZContext()) {
            ZMQ.Socket req = ctx.createSocket(SocketType.REQ);
            req.setReceiveTimeOut((int) EngineFixture.TIMEOUT);
            Connect.connect(req, f.endpoints.skill());
            req.send("{\"id\":1,\"msg-type\":\"push-skill\",\"skill\":{\"name\":\"GoTo\"}} trailing");
            assertNotNull("acked", req.recv());
        }
        assertEquals(1, f.skills.malformedRequests());
        assertTrue("not run as a skill", f.skills.pushed().isEmpty());
    }

    @Test
    public void filesWithTrailingGarbageAreRejected() throws Exception {
        f = new EngineFixture(tmp.getRoot().toPath());
        Path scenario = tmp.newFile("s.json").toPath();
        Files.writeString(scenario, "[{\"at\":0,\"estimate\":{\"name\":\"safety\",\"value\":0.5}}] ]");
        expectIoError(() -> Scenario.load(scenario));
        Path table = tmp.newFile("t.json").toPath();
        Files.writeString(table, "{\"GoTo\":{\"duration\":10}} {}");
        expectIoError(() -> SkillTable.load(table));
        Files.writeString(f.ioJson, Files.readString(f.ioJson) + "\n{\"format\":1}");
        try {
            IoModel.load(f.ioJson);
            fail("io.json with a second value accepted");
        } catch (IllegalArgumentException expected) {
            // named in the message, as any other io.json problem
        }
    }

    private interface Load {
        void run() throws IOException;
    }

    private static void expectIoError(Load load) {
        try {
            load.run();
            fail("trailing garbage accepted");
        } catch (IOException expected) {
            // the command prints it as a start-up error
        }
    }
}
