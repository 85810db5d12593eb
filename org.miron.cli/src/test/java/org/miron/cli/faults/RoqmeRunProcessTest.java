package org.miron.cli.faults;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.cli.MironCli;
import org.miron.runtime.Endpoints;
import org.miron.runtime.broker.Broker;
import org.miron.runtime.bus.BusClient;
import org.miron.runtime.bus.Topics;
import org.miron.testkit.runtime.BusProbe;
import org.miron.testkit.runtime.TestModels;

/** {@code miron roqme run} as a real process: estimates and observations on the bus, SIGTERM as its help says. */
public class RoqmeRunProcessTest {
    private static final long TIMEOUT = 30_000;
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();

    @Test
    public void publishesAndStopsOnSigterm() throws Exception {
        Path dir = tmp.getRoot().toPath();
        Path model = TestModels.copyRoqme("intralogistics.roqme.json", dir);
        String help = MironCli.commandLine().getSubcommands().get("roqme").getSubcommands().get("run").getUsageMessage();
        Matcher m = Pattern.compile("(?m)^\\s*(\\d+)\\s+.*SIGTERM").matcher(help);
        assertTrue(help, m.find());
        Endpoints ep = Endpoints.freeLoopback();
        try (Broker broker = new Broker(ep).start();
                BusProbe probe = new BusProbe(ep.busOut(), "roqme.");
                BusClient input = new BusClient("test-input", ep.busIn(), null, List.of(), (t, b) -> { }).start();
                RuntimeProcess p = RuntimeProcess.start(dir, "roqme", "roqme", "run", model.toString(), "--period", "200",
                        "--param", "LowBattery=40", "--bus-in", ep.busIn(), "--bus-out", ep.busOut())) {
            assertTrue(p.output(), p.awaitOutput("miron roqme run: model intralogistics", TIMEOUT));
            assertNotNull(p.output(), probe.await(Topics.ESTIMATE, b -> b.path("name").asText().equals("power_autonomy"), TIMEOUT));
            assertTrue(input.awaitReady(TIMEOUT));
            long end = System.currentTimeMillis() + TIMEOUT;
            while (probe.messages(Topics.OBSERVATION).isEmpty() && System.currentTimeMillis() < end) {
                // 35 < LowBattery given on the command line (40), above the default (30)
                input.publish(Topics.CONTEXT, "{\"name\":\"BatteryLevel\",\"namespace\":\"Intralogistics\",\"type\":\"number\",\"value\":35}");
                Thread.sleep(200);
            }
            assertEquals("batteryLow", probe.messages(Topics.OBSERVATION).get(0).body().path("name").asText());
            assertEquals(Integer.parseInt(m.group(1)), p.terminate(TIMEOUT));
        }
    }
}
