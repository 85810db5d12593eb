package org.miron.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Endpoints;
import org.miron.testkit.runtime.TestModels;
import picocli.CommandLine;

public class CommandsTest {
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();

    /** Runs a command, returning exit code and everything printed on stderr. */
    private static String[] run(Object command, String... args) {
        PrintStream oldErr = System.err;
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        StringWriter picocliErr = new StringWriter();
        int code;
        try {
            System.setErr(new PrintStream(err, true));
            CommandLine cl = new CommandLine(command);
            cl.setErr(new PrintWriter(picocliErr, true));
            code = cl.execute(args);
        } finally {
            System.setErr(oldErr);
        }
        return new String[] {Integer.toString(code), err + picocliErr.toString()};
    }

    @Test
    public void engineWithoutMinizincFailsWithAClearMessage() throws Exception {
        Path io = TestModels.copy("testbot", tmp.getRoot().toPath());
        Endpoints ep = Endpoints.freeLoopback();
        String[] r = run(new EngineCommand(), "--io", io.toString(), "--minizinc", "/nonexistent/minizinc",
                "--bus-in", ep.busIn(), "--bus-out", ep.busOut(), "--request", ep.request(),
                "--decision-log", tmp.getRoot() + "/d.jsonl");
        assertEquals("2", r[0]);
        assertTrue(r[1], r[1].startsWith("miron engine: error: cannot run MiniZinc executable '/nonexistent/minizinc'"));
        assertFalse("no stack trace: " + r[1], r[1].contains("\tat "));
    }

    /** Every command's help is printed as written: picocli warns on stderr of a lone % in a description. */
    @Test
    public void everyCommandsHelpPrintsWithoutAWarning() {
        java.util.ArrayDeque<CommandLine> open = new java.util.ArrayDeque<>(java.util.List.of(MironCli.commandLine()));
        int commands = 0;
        while (!open.isEmpty()) {
            CommandLine cl = open.poll();
            open.addAll(cl.getSubcommands().values());
            PrintStream oldErr = System.err;
            ByteArrayOutputStream err = new ByteArrayOutputStream();
            String help;
            try {
                System.setErr(new PrintStream(err, true));
                help = cl.getUsageMessage();
            } finally {
                System.setErr(oldErr);
            }
            assertEquals(cl.getCommandName() + ": " + err, "", err.toString());
            assertFalse(cl.getCommandName() + " help: " + help, help.contains("%n"));
            commands++;
        }
        assertTrue("every command visited: " + commands, commands > 10);
    }

    @Test
    public void engineRequiresIo() {
        String[] r = run(new EngineCommand());
        assertEquals("2", r[0]);
        assertTrue(r[1], r[1].contains("--io"));
    }

    @Test
    public void playReportsAMissingScenarioFile() {
        String[] r = run(new PlayCommand(), tmp.getRoot() + "/none.json");
        assertEquals("2", r[0]);
        assertTrue(r[1], r[1].startsWith("miron play: error:"));
    }

    @Test
    public void skillMockReportsABadSkillTable() throws Exception {
        Path table = tmp.newFile("skills.json").toPath();
        Files.writeString(table, "{\"GoTo\": {\"result\": \"MAYBE\"}}");
        String[] r = run(new SkillMockCommand(), "--skills", table.toString());
        assertEquals("2", r[0]);
        assertTrue(r[1], r[1].contains("MAYBE"));
    }

    @Test
    public void playPublishesAScenarioThroughABroker() throws Exception {
        Endpoints ep = Endpoints.freeLoopback();
        Path scenario = tmp.newFile("s.json").toPath();
        Files.writeString(scenario, "[{\"at\": 0, \"estimate\": {\"name\": \"safety\", \"value\": 0.4}},"
                + " {\"at\": 50, \"context\": {\"name\": \"Door\", \"type\": \"event\", \"value\": true}}]");
        try (org.miron.runtime.broker.Broker broker = new org.miron.runtime.broker.Broker(ep).start()) {
            String[] r = run(new PlayCommand(), scenario.toString(), "--time-scale", "0.5", "--bus-in", ep.busIn());
            assertEquals(r[1], "0", r[0]);
            long end = System.currentTimeMillis() + 10_000;
            // plus the broker's own miron.broker.hello
            while (broker.cachedTopics() < 3 && System.currentTimeMillis() < end) {
                Thread.sleep(10);
            }
            assertEquals("both steps reached the broker's cache", 3, broker.cachedTopics());
        }
    }

    @Test
    public void brokerOnABusyPortFailsWithAClearMessage() throws Exception {
        Endpoints ep = Endpoints.freeLoopback();
        try (org.miron.runtime.broker.Broker first = new org.miron.runtime.broker.Broker(ep).start()) {
            String[] r = run(new BrokerCommand(), "--request", ep.request(), "--skill", ep.skill(),
                    "--bus-in", ep.busIn(), "--bus-out", ep.busOut());
            assertEquals("2", r[0]);
            // which endpoint and why, in words (JeroMQ itself says "Errno 48")
            assertTrue(r[1], r[1].startsWith("miron broker: error: broker cannot bind its endpoints: " + ep.request()
                    + ": address already in use"));
        }
    }

    @Test
    public void mironListsTheRuntimeSubcommands() {
        CommandLine cl = MironCli.commandLine();
        assertTrue(cl.getSubcommands().keySet().toString(), cl.getSubcommands().keySet()
                .containsAll(java.util.Set.of("broker", "engine", "skill-mock", "play", "execute")));
        String usage = cl.getSubcommands().get("engine").getUsageMessage();
        assertTrue(usage, usage.contains("--backend") && usage.contains("5561"));
    }
}
