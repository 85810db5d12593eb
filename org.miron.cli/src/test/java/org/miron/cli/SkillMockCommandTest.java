package org.miron.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * `miron skill-mock --world`: the world is checked against the model before the mock starts; a
 * world the model's tree cannot meet is refused with positions, as `miron simulate` refuses it.
 * (The mock acting on a world over its sockets: LiveWorldTest; in the demo: DemoCommandTest.)
 */
public class SkillMockCommandTest {
    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    @Test
    public void aWorldNeedsTheModelItIsCheckedAgainst() {
        Cli cli = new Cli();
        assertEquals(2, cli.run("skill-mock", "--world", Cli.ROOT.resolve("examples/intralogistics/demo/world.json").toString()));
        assertTrue(cli.err.toString(), cli.err.toString().contains("--world needs --model MODEL.miron"));
    }

    @Test
    public void aWorldWithASkillTheTreeDoesNotPushIsRefusedWithItsPosition() throws Exception {
        String world = Files.readString(Cli.ROOT.resolve("examples/intralogistics/demo/world.json"))
                .replace("\"objectdrop\": {", "\"objectthrow\": {");
        Path file = Cli.write(temp.getRoot().toPath(), "world.json", world);
        Cli cli = new Cli();
        assertEquals(2, cli.run("skill-mock", "--world", file.toString(), "--model",
                Cli.ROOT.resolve("examples/intralogistics/intralogistics.miron").toString(), "--rep", "tcp://127.0.0.1:1",
                "--pub", "tcp://127.0.0.1:2"));
        String err = cli.err.toString();
        assertTrue(err, err.matches("(?s).*world\\.json:\\d+:\\d+: error \\[[a-z.-]+\\]: .*objectthrow.*"));
        assertTrue(err, !err.contains("Exception"));
    }
}
