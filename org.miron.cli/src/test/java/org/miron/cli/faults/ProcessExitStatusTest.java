package org.miron.cli.faults;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.After;
import org.junit.Before;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Endpoints;
import org.miron.runtime.broker.Broker;
import org.miron.cli.MironCli;
import org.miron.runtime.skill.SkillInterfaceMock;
import org.miron.runtime.skill.SkillTable;
import org.miron.testkit.runtime.TestModels;
import picocli.CommandLine;

/**
 * Issue 10, item 7: every long-running command, run as a real process and stopped with SIGTERM
 * once it is up, exits with the status its {@code --help} documents for SIGTERM.
 */
public class ProcessExitStatusTest {
    private static final long TIMEOUT = 30_000;
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();
    private final Endpoints ep = Endpoints.freeLoopback();
    private Path dir;

    @Before
    public void setUp() {
        dir = tmp.getRoot().toPath();
    }

    /** The status the command's help gives for SIGTERM, e.g. "143:stopped by SIGTERM" → 143. */
    private static int documentedSigterm(String command) {
        String help = MironCli.commandLine().getSubcommands().get(command).getUsageMessage();
        Matcher m = Pattern.compile("(?m)^\\s*(\\d+)\\s+.*SIGTERM").matcher(help);
        assertTrue(command + " --help documents the SIGTERM exit status:\n" + help, m.find());
        return Integer.parseInt(m.group(1));
    }

    private void assertSigtermStatus(String command, String readyText, String... args) throws Exception {
        int documented = documentedSigterm(command);
        String[] full = new String[args.length + 1];
        full[0] = command;
        System.arraycopy(args, 0, full, 1, args.length);
        try (RuntimeProcess p = RuntimeProcess.start(dir, command, full)) {
            assertTrue(command + " comes up:\n" + p.output(), p.awaitOutput(readyText, TIMEOUT));
            int status = p.terminate(TIMEOUT);
            assertEquals(command + " exit status on SIGTERM vs its --help:\n" + p.output(), documented, status);
        }
    }

    @Test
    public void broker() throws Exception {
        assertSigtermStatus("broker", "broker: requests", "--request", ep.request(), "--skill", ep.skill(),
                "--bus-in", ep.busIn(), "--bus-out", ep.busOut());
    }

    @Test
    public void skillMock() throws Exception {
        assertSigtermStatus("skill-mock", "skill interface mock: queries", "--rep", ep.skill(), "--pub", ep.skillEvents());
    }

    @Test
    public void engine() throws Exception {
        TestModels.copy("testbot", dir);
        try (Broker broker = new Broker(ep).start()) {
            assertSigtermStatus("engine", "engine: model", "--io", dir.resolve("testbot.io.json").toString(),
                    "--bus-in", ep.busIn(), "--bus-out", ep.busOut(), "--request", ep.request(),
                    "--decision-log", dir.resolve("d.jsonl").toString());
        }
    }

    @Test
    public void play() throws Exception {
        Path scenario = dir.resolve("s.json");
        Files.writeString(scenario, "[{\"at\":0,\"estimate\":{\"name\":\"safety\",\"namespace\":\"N\",\"value\":0.5}},"
                + "{\"at\":600000,\"estimate\":{\"name\":\"safety\",\"namespace\":\"N\",\"value\":0.6}}]");
        try (Broker broker = new Broker(ep).start()) {
            assertSigtermStatus("play", "played roqme.estimate", scenario.toString(), "--bus-in", ep.busIn());
        }
    }

    @Test
    public void execute() throws Exception {
        Path tree = dir.resolve("t.bt");
        Files.writeString(tree, "<?xml version=\"1.0\"?>\n<root>\n  <BehaviorTree ID=\"Only\">\n"
                + "    <Sequence>\n      <Action ID=\"Wait\"/>\n    </Sequence>\n  </BehaviorTree>\n</root>\n");
        SkillTable table = new SkillTable(java.util.Map.of("Wait", new SkillTable.Entry(600_000, "SUCCESS",
                com.fasterxml.jackson.databind.node.NullNode.getInstance(), org.miron.runtime.Json.object())));
        try (Broker broker = new Broker(ep).start();
                SkillInterfaceMock skills = new SkillInterfaceMock(ep.skill(), ep.skillEvents(), table).start()) {
            assertSigtermStatus("execute", "RUNNING", tree.toString(), "--request", ep.request(),
                    "--skill-events", ep.skillEvents(), "--bus-in", ep.busIn(), "--bus-out", ep.busOut());
        }
    }

    /** With --repeat the tree runs mission after mission, failed or not, until the signal. */
    @Test
    public void executeRepeat() throws Exception {
        Path tree = dir.resolve("t.bt");
        Files.writeString(tree, "<?xml version=\"1.0\"?>\n<root>\n  <BehaviorTree ID=\"Round\">\n"
                + "    <Sequence>\n      <Action ID=\"Fetch\"/>\n      <Action ID=\"Drop\"/>\n    </Sequence>\n"
                + "  </BehaviorTree>\n</root>\n");
        com.fasterxml.jackson.databind.JsonNode none = com.fasterxml.jackson.databind.node.NullNode.getInstance();
        SkillTable table = new SkillTable(java.util.Map.of(
                "Fetch", new SkillTable.Entry(50, "SUCCESS", none, org.miron.runtime.Json.object()),
                "Drop", new SkillTable.Entry(50, "FAILURE", none, org.miron.runtime.Json.object())));
        int documented = documentedSigterm("execute");
        try (Broker broker = new Broker(ep).start();
                SkillInterfaceMock skills = new SkillInterfaceMock(ep.skill(), ep.skillEvents(), table).start();
                RuntimeProcess p = RuntimeProcess.start(dir, "execute", "execute", tree.toString(), "--repeat",
                        "--request", ep.request(), "--skill-events", ep.skillEvents(), "--bus-in", ep.busIn(),
                        "--bus-out", ep.busOut())) {
            long end = System.currentTimeMillis() + TIMEOUT;
            while (p.output().split("tree Round finished: FAILURE, starting again", -1).length < 4
                    && System.currentTimeMillis() < end) {
                Thread.sleep(20);
            }
            assertTrue("three rounds:\n" + p.output(),
                    p.output().split("tree Round finished: FAILURE, starting again", -1).length >= 4);
            assertEquals(p.output(), documented, p.terminate(TIMEOUT));
        }
    }
}
