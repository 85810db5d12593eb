package org.miron.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * `miron generate` and `miron check` as a user runs them: a model with errors prints them all
 * (file:line:col) and writes nothing; bad command lines exit 2. What the generated files hold is
 * tested in org.miron.generator (ExamplesGenerationTest).
 */
public class GenerateCommandTest {
    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    private Path write(String name, String text) throws IOException {
        return Cli.write(temp.getRoot().toPath(), name, text);
    }

    private void copyIntralogistics() throws IOException {
        for (String f : List.of("intralogistics.bt", "intralogistics.roqme")) {
            Files.copy(Cli.ROOT.resolve("examples/intralogistics/" + f), temp.getRoot().toPath().resolve(f));
        }
    }

    @Test
    public void modelErrorsArePrintedAndNothingIsGenerated() throws IOException {
        copyIntralogistics();
        Path model = write("broken.miron", "import \"intralogistics.bt\" as main\nimport \"intralogistics.roqme\" as roqme\n\n"
                + "@varpoint task : enum { dock : main.Charge, nominal : preset } in main.NoSuchNode\n\n"
                + "rule r : roqme.no_such_property < 0.3 implies task = task::dock\n");
        Path out = temp.getRoot().toPath().resolve("out");
        Cli cli = new Cli();
        assertEquals(1, cli.run("generate", model.toString(), "-o", out.toString()));
        String[] lines = cli.out().split("\n");
        assertEquals(cli.out(), 2, lines.length);
        assertTrue(lines[0], lines[0].matches(".*broken\\.miron:4:\\d+: error \\[roqme\\.unknown-reference\\]: .*NoSuchNode.*"));
        assertTrue(lines[1], lines[1].matches(".*broken\\.miron:6:\\d+: error \\[roqme\\.unknown-reference\\]: .*no_such_property.*"));
        assertFalse("nothing may be written", Files.exists(out));
    }

    @Test
    public void rulesWithoutMiniZincMeaningArePositionedErrors() throws IOException {
        copyIntralogistics();
        Path model = write("timer.miron", "import \"intralogistics.bt\" as main\nimport \"intralogistics.roqme\" as roqme\n\n"
                + "@varpoint task : enum { dock : main.Charge, nominal : preset } in main.PickDeliverChargeSubtree\n\n"
                + "rule many : count(roqme.DeliveryDone, 10 minutes) > 3 implies task = task::dock\n");
        Path out = temp.getRoot().toPath().resolve("out");
        Cli cli = new Cli();
        assertEquals(1, cli.run("generate", model.toString(), "-o", out.toString()));
        assertTrue(cli.out(), cli.out().matches("(?s).*timer\\.miron:6:13: error: cannot generate MiniZinc for 'count.*"));
        assertFalse("nothing may be written", Files.exists(out));
    }

    @Test
    public void aRoqmeModelGeneratesItsRuntimeModelOnly() throws IOException {
        copyIntralogistics();
        Path out = temp.getRoot().toPath().resolve("out");
        Cli cli = new Cli();
        Path model = temp.getRoot().toPath().resolve("intralogistics.roqme");
        assertEquals(cli.out(), 0, cli.run("generate", model.toString(), "-o", out.toString()));
        assertEquals("wrote " + out.resolve("intralogistics.roqme.json"), cli.out().strip());
        try (Stream<Path> files = Files.list(out)) {
            assertEquals(List.of(out.resolve("intralogistics.roqme.json")), files.toList());
        }
        String json = Files.readString(out.resolve("intralogistics.roqme.json"));
        assertTrue(json, json.contains("\"source\": \"intralogistics.roqme\""));
        assertTrue(json, json.contains("\"id\": \"batteryLow\""));
    }

    @Test
    public void aRoqmeModelTheRuntimeModelCannotHoldIsRefusedWithItsPosition() throws IOException {
        Path model = write("bad.roqme", "param every : time default 5 seconds\ntimer tick := every\n"
                + "property p\nobservation o : tick reinforces p\n");
        Path out = temp.getRoot().toPath().resolve("out");
        Cli cli = new Cli();
        assertEquals(1, cli.run("generate", model.toString(), "-o", out.toString()));
        assertTrue(cli.out(), cli.out().matches(
                "(?s).*bad\\.roqme:2:15: error \\[roqme\\.unsupported-timer-period\\]: the period of timer 'tick'.*"));
        assertFalse("nothing may be written", Files.exists(out));
    }

    @Test
    public void usageErrorsExitWithTwo() throws IOException {
        String model = Cli.ROOT.resolve("examples/intralogistics/intralogistics.miron").toString();
        assertEquals(2, Cli.exit("generate"));
        assertEquals(2, Cli.exit("generate", model, "--weights", "fair"));
        assertEquals(2, Cli.exit("generate", temp.getRoot().toPath().resolve("missing.miron").toString()));
        assertEquals(2, Cli.exit("generate", Cli.ROOT.resolve("examples/intralogistics/intralogistics.bt").toString()));
        assertEquals(2, Cli.exit("generate", model, "--no-such-option"));
    }

    @Test
    public void checkAcceptsMironModelsAndWhatTheyImport() throws IOException {
        assertEquals(0, Cli.exit("check", Cli.ROOT.resolve("examples/intralogistics/intralogistics.miron").toString()));
        assertEquals(0, Cli.exit("check", Cli.ROOT.resolve("examples/intralogistics/intralogistics.roqme").toString()));
        copyIntralogistics();
        Path model = write("bad.miron", "import \"intralogistics.bt\" as main\n\n@varpoint v : enum { a : main.Nope, b : preset } in main.Charge\n");
        Cli cli = new Cli();
        assertEquals(1, cli.run("check", model.toString()));
        assertTrue(cli.out(), cli.out().matches("(?s).*bad\\.miron:3:\\d+: error \\[roqme\\.unknown-reference\\]: .*Nope.*"));
    }
}
