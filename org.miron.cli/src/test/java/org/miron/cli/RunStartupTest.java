package org.miron.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Endpoints;
import org.miron.runtime.broker.Broker;

/**
 * {@code miron run} in process, all or nothing: a component that cannot start stops the ones
 * started before it (their endpoints are free again) and the reason is printed; a bad bridge
 * configuration is refused before anything starts.
 */
public class RunStartupTest {
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();
    private final Endpoints ep = Endpoints.freeLoopback();
    private final Cli cli = new Cli();

    private int run(String... extra) {
        String[] base = { "run", Cli.ROOT.resolve("examples/intralogistics/intralogistics.miron").toString(), "--request", ep.request(),
                "--skill", ep.skill(), "--bus-in", ep.busIn(), "--bus-out", ep.busOut(),
                "--decision-log", tmp.getRoot().toPath().resolve("d.jsonl").toString() };
        String[] all = new String[base.length + extra.length];
        System.arraycopy(base, 0, all, 0, base.length);
        System.arraycopy(extra, 0, all, base.length, extra.length);
        return cli.run(all);
    }

    @Test
    public void anEngineThatCannotStartStopsTheOthersAndSaysWhy() {
        assertEquals(2, run("--backend", "minizinc", "--minizinc", "/nonexistent/minizinc"));
        String err = cli.err.toString();
        assertTrue(err, err.contains("miron run: error: engine: cannot run MiniZinc executable '/nonexistent/minizinc'"));
        assertTrue(err, err.contains("(nothing runs)"));
        assertTrue(cli.out(), cli.out().contains("miron run: broker: requests " + ep.request()));
        assertFalse(cli.out(), cli.out().contains("miron run: running"));
        // the broker that had started released its endpoints: start() would throw on a bound one
        new Broker(ep).start().close();
    }

    @Test
    public void aBadBridgeConfigurationIsRefusedBeforeAnythingStarts() throws Exception {
        Path config = Cli.write(tmp.getRoot().toPath(), "bridge.json", """
                {"contexts": [{"topic": "battery_state", "type": "sensor_msgs/BatteryState",
                               "field": "header.stamp.nsec", "context": "Stamp"}]}
                """);
        assertEquals(2, run("--dds-bridge", config.toString()));
        assertTrue(cli.err.toString(), cli.err.toString().startsWith(config + ":2:25: error [dds-config]: /contexts/0/field"));
        assertEquals("", cli.out());
    }

    @Test
    public void aModelThatIsNotMironIsAUsageError() throws Exception {
        Path bt = Cli.ROOT.resolve("examples/intralogistics/intralogistics.bt");
        assertEquals(2, cli.run("run", bt.toString()));
        assertTrue(cli.err.toString(), cli.err.toString().startsWith(bt + ": error: miron run needs a .miron model"));
    }
}
