package org.miron.generator;

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
 * `miron generate` as a user runs it: every example generates, its woven tree passes our BT
 * validation, its io.json follows docs/io-json.schema.json and its MiniZinc model solves; output is deterministic and relative; a model with
 * errors prints them all (file:line:col) and writes nothing; bad command lines exit 2.
 */
public class GenerateCommandTest {
    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    private static List<Path> examples() throws IOException {
        List<Path> models = new ArrayList<>();
        try (Stream<Path> files = Files.walk(Cli.ROOT.resolve("examples"), 2)) {
            files.filter(f -> f.toString().endsWith(".miron")).sorted().forEach(models::add);
        }
        assertFalse("no examples/*/*.miron", models.isEmpty());
        return models;
    }

    private static String base(Path model) {
        return model.getFileName().toString().replaceFirst("\\.miron$", "");
    }

    @Test
    public void everyExampleGeneratesChecksAndSolves() throws IOException {
        for (Path model : examples()) {
            Path out = temp.newFolder(base(model)).toPath();
            Cli cli = new Cli();
            assertEquals(model + ": " + cli.out() + cli.err, 0, cli.run("generate", model.toString(), "-o", out.toString()));
            for (String ext : List.of(".ext.xml", ".mzn", ".dzn", ".io.json")) {
                assertTrue(model + " did not generate " + ext, Files.isRegularFile(out.resolve(base(model) + ext)));
            }
            Cli check = new Cli();
            assertEquals(model + ": " + check.out(), 0, check.run("check", out.resolve(base(model) + ".ext.xml").toString()));
            IoJsonSchema.assertValid(out.resolve(base(model) + ".io.json"));
            MiniZinc mzn = new MiniZinc(out.resolve(base(model) + ".io.json"));
            Map<String, Integer> decisions = mzn.solve(mzn.defaults());
            assertEquals(model + ": one decision per varpoint", mzn.io.get("varpoints").size(), decisions.size());
        }
    }

    @Test
    public void everyExampleSolvesForSeveralSituations() throws IOException {
        for (Path model : examples()) {
            Path out = temp.newFolder(base(model) + "-situations").toPath();
            assertEquals(0, Cli.exit("generate", model.toString(), "-o", out.toString()));
            MiniZinc mzn = new MiniZinc(out.resolve(base(model) + ".io.json"));
            for (double level : new double[] { 0.05, 0.5, 0.95 }) {
                for (boolean known : new boolean[] { false, true }) {
                    com.fasterxml.jackson.databind.node.ObjectNode data = mzn.defaults();
                    for (com.fasterxml.jackson.databind.JsonNode in : mzn.io.get("inputs")) {
                        if (in.get("kind").asText().equals("metric")) {
                            data.put(in.get("param").asText(), level);
                        } else {
                            data.put(in.get("known").asText(), known);
                        }
                    }
                    Map<String, Integer> decisions = mzn.solve(data);
                    for (com.fasterxml.jackson.databind.JsonNode vp : mzn.io.get("varpoints")) {
                        Integer d = decisions.get(vp.get("decision").asText());
                        assertTrue(model + " " + data + ": " + decisions,
                                d != null && d >= 0 && d < vp.get("values").size());
                    }
                }
            }
        }
    }

    @Test
    public void outputIsDeterministicAndRelative() throws IOException {
        for (Path model : examples()) {
            Path first = temp.newFolder(base(model) + "1").toPath();
            Path second = temp.newFolder(base(model) + "2").toPath();
            assertEquals(0, Cli.exit("generate", model.toString(), "-o", first.toString()));
            assertEquals(0, Cli.exit("generate", model.toString(), "-o", second.toString()));
            try (Stream<Path> files = Files.list(first)) {
                for (Path file : (Iterable<Path>) files::iterator) {
                    String text = Files.readString(file);
                    assertEquals(file + " differs on re-run", text, Files.readString(second.resolve(file.getFileName())));
                    assertFalse(file + " holds an absolute path", text.contains(temp.getRoot().getAbsolutePath())
                            || text.contains(Cli.ROOT.toString()));
                }
            }
        }
    }

    @Test
    public void ioJsonParametersAreThoseOfTheModel() throws IOException {
        Path out = temp.newFolder("io").toPath();
        assertEquals(0, Cli.exit("generate", Cli.ROOT.resolve("examples/intralogistics/intralogistics.miron").toString(),
                "-o", out.toString()));
        MiniZinc mzn = new MiniZinc(out.resolve("intralogistics.io.json"));
        String model = Files.readString(out.resolve("intralogistics.mzn"));
        mzn.defaults().fieldNames().forEachRemaining(param -> assertTrue(param + " is not a parameter of the .mzn",
                model.matches("(?s).*\\n(float|bool|int): " + param + ";.*")));
        assertEquals("intralogistics.ext.xml", mzn.io.get("tree").asText());
        assertEquals("need", mzn.io.get("weights").asText());
        assertEquals(3, mzn.varpoint("task").get("preset").asInt());
        assertEquals("arch", mzn.varpoint("maxVelocity").get("binding").get("type").asText());
        assertEquals("[\"PickDeliverChargeSubtree\"]", mzn.varpoint("task").get("binding").get("targets").toString());
    }

    private Path write(String name, String text) throws IOException {
        Path file = temp.getRoot().toPath().resolve(name);
        Files.createDirectories(file.getParent());
        Files.writeString(file, text);
        return file;
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
