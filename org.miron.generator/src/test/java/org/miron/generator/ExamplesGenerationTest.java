package org.miron.generator;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.testkit.JsonSchemaFile;

/**
 * Every example generates, its woven tree passes our BT validation, its io.json follows
 * docs/io-json.schema.json and its MiniZinc model solves; output is deterministic and relative.
 */
public class ExamplesGenerationTest {
    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    private static List<Path> examples() throws IOException {
        List<Path> models = Toolchain.exampleModels();
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
            Toolchain toolchain = new Toolchain();
            assertEquals(model + ": " + toolchain.messages(), 0, toolchain.generate(model.toString(), out.toString()));
            for (String ext : List.of(".ext.xml", ".mzn", ".dzn", ".io.json", ".requirements.json")) {
                assertTrue(model + " did not generate " + ext, Files.isRegularFile(out.resolve(base(model) + ext)));
            }
            Toolchain check = new Toolchain();
            assertEquals(model + ": " + check.messages(), 0, check.check(out.resolve(base(model) + ".ext.xml").toString()));
            JsonSchemaFile.IO_JSON.assertValid(out.resolve(base(model) + ".io.json"));
            JsonSchemaFile.REQUIREMENTS.assertValid(out.resolve(base(model) + ".requirements.json"));
            MiniZinc mzn = new MiniZinc(out.resolve(base(model) + ".io.json"));
            Map<String, Integer> decisions = mzn.solve(mzn.defaults());
            assertEquals(model + ": one decision per varpoint", mzn.io.get("varpoints").size(), decisions.size());
        }
    }

    @Test
    public void everyExampleSolvesForSeveralSituations() throws IOException {
        for (Path model : examples()) {
            Path out = temp.newFolder(base(model) + "-situations").toPath();
            assertEquals(0, new Toolchain().generate(model.toString(), out.toString()));
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
            assertEquals(0, new Toolchain().generate(model.toString(), first.toString()));
            assertEquals(0, new Toolchain().generate(model.toString(), second.toString()));
            try (Stream<Path> files = Files.list(first)) {
                for (Path file : (Iterable<Path>) files::iterator) {
                    String text = Files.readString(file);
                    assertEquals(file + " differs on re-run", text, Files.readString(second.resolve(file.getFileName())));
                    assertFalse(file + " holds an absolute path", text.contains(temp.getRoot().getAbsolutePath())
                            || text.contains(Toolchain.ROOT.toString()));
                }
            }
        }
    }

    @Test
    public void ioJsonParametersAreThoseOfTheModel() throws IOException {
        Path out = temp.newFolder("io").toPath();
        assertEquals(0, new Toolchain().generate(Toolchain.ROOT.resolve("examples/intralogistics/intralogistics.miron").toString(), out.toString()));
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

}
