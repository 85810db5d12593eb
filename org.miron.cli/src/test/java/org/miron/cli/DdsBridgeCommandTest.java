package org.miron.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * {@code miron dds-bridge} refuses a bad configuration before it touches DDS: one line with the
 * file, line, column and JSON pointer, exit 2. (The bridge at work is tested against a real DDS
 * peer in org.miron.dds, DdsBridgeTest.)
 */
public class DdsBridgeCommandTest {
    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    private final Cli cli = new Cli();

    @Test
    public void aBadConfigurationIsRefusedWithItsPosition() throws IOException {
        Path config = Cli.write(temp.getRoot().toPath(), "bridge.json", """
                {"contexts": [{"topic": "battery_state", "type": "sensor_msgs/BatteryState",
                               "field": "header.stamp.nsec", "context": "Stamp"}]}
                """);
        assertEquals(2, cli.run("dds-bridge", "--config", config.toString()));
        String err = cli.err.toString().trim();
        assertTrue(err, err.startsWith(config + ":2:25: error [dds-config]: /contexts/0/field: sensor_msgs/BatteryState has no value field \"header.stamp.nsec\""));
        assertEquals(1, err.lines().count());
    }

    @Test
    public void aBadMessageDefinitionIsADdsTypesErrorAtItsToken() throws IOException {
        Path root = temp.getRoot().toPath();
        Path msg = Cli.write(root, "msgs/my_robot_msgs/msg/PowerStatus.msg", "# the battery driver's message\nstd_msgs/Header header\n  flaot32 charge_percent\n");
        Path config = Cli.write(root, "bridge.json", """
                {"messages": ["msgs/my_robot_msgs"],
                 "contexts": [{"topic": "power_status", "type": "my_robot_msgs/PowerStatus", "field": "charge_percent", "context": "BatteryLevel"}]}
                """);
        assertEquals(2, cli.run("dds-bridge", "--config", config.toString()));
        String err = cli.err.toString().trim();
        assertTrue(err, err.startsWith(msg.toAbsolutePath().normalize() + ":3:3: error [dds-types]: unknown type flaot32"));
        assertTrue(err, err.endsWith("did you mean float32?"));
        assertEquals(1, err.lines().count());
    }

    @Test
    public void aMissingFileOrBadOptionIsAUsageError() {
        assertEquals(2, cli.run("dds-bridge", "--config", temp.getRoot().toPath().resolve("none.json").toString()));
        assertTrue(cli.err.toString(), cli.err.toString().startsWith("miron dds-bridge: error: cannot read "));
        assertEquals(2, cli.run("dds-bridge"));
        assertTrue(cli.err.toString(), cli.err.toString().contains("Missing required option: '--config=FILE'"));
    }
}
