package org.miron.generator;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.testkit.JsonSchemaFile;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * The generator's side of the io.json contract (docs/io-json.schema.json): what it writes is valid,
 * the schema really rejects what the engine could not use, and strings of the model reach the
 * file intact whatever characters they hold.
 */
public class IoJsonContractTest {
    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    private static final ObjectMapper MAPPER = new ObjectMapper();

    private ObjectNode generateIntralogistics() throws IOException {
        Path out = temp.newFolder("out").toPath();
        assertEquals(0, new Toolchain().generate(Toolchain.ROOT.resolve("examples/intralogistics/intralogistics.miron").toString(), out.toString()));
        return (ObjectNode) MAPPER.readTree(out.resolve("intralogistics.io.json").toFile());
    }

    private static ObjectNode varpoint(ObjectNode io, int i) {
        return (ObjectNode) io.get("varpoints").get(i);
    }

    @Test
    public void generatedFileIsValid() throws IOException {
        assertEquals(List.of(), JsonSchemaFile.IO_JSON.problems(generateIntralogistics()));
    }

    @Test
    public void exampleOfTheDocumentationIsValid() throws IOException {
        String doc = Files.readString(Toolchain.ROOT.resolve("docs/io-json.md"));
        int start = doc.indexOf("```json\n") + "```json\n".length();
        assertTrue("docs/io-json.md has a ```json example", start > "```json\n".length() - 1);
        String example = doc.substring(start, doc.indexOf("```", start));
        assertEquals(List.of(), JsonSchemaFile.IO_JSON.problems(example));
    }

    @Test
    public void layoutKeepsValuesOnOneLineAndObjectsApart() throws IOException {
        Path out = temp.newFolder("layout").toPath();
        assertEquals(0, new Toolchain().generate(Toolchain.ROOT.resolve("examples/intralogistics/intralogistics.miron").toString(), out.toString()));
        String text = Files.readString(out.resolve("intralogistics.io.json"));
        assertTrue(text, text.startsWith("{\n  \"format\": 1,\n  \"model\": \"intralogistics\",\n"));
        assertTrue(text, text.contains("\n      \"values\": [\"pick\", \"deliver\", \"dock\", \"pickDeliverCharge\"],\n"));
        assertTrue(text, text.contains("\n  \"varpoints\": [\n    {\n      \"name\": \"task\",\n"));
        assertTrue(text, text.contains("\n    }\n  ],\n  \"decision\": {\n    \"objective\": \"maximize\",\n"));
        assertTrue(text, text.endsWith("\n  }\n}\n"));
    }

    @Test
    public void schemaRejectsWhatTheEngineCannotUse() throws IOException {
        ObjectNode good = generateIntralogistics();
        List<java.util.function.Consumer<ObjectNode>> breakages = List.of(
                io -> varpoint(io, 0).remove("decision"),
                io -> varpoint(io, 0).put("kind", "set"),
                io -> varpoint(io, 0).putArray("values"),
                io -> ((ArrayNode) varpoint(io, 0).get("values")).add(3), // a number among enum labels
                io -> varpoint(io, 0).put("preset", -1),
                io -> ((ObjectNode) varpoint(io, 0).get("binding")).put("type", "ros"),
                io -> ((ObjectNode) io.get("inputs").get(0)).put("type", "string"),
                io -> io.put("format", 2),
                io -> io.remove("mzn"),
                io -> io.put("unexpected", true),
                io -> ((ObjectNode) io.get("decision")).put("objective", "minimize"),
                io -> ((ObjectNode) io.get("decision").get("rules").get(0)).putObject("condition").put("op", "xor"));
        for (int i = 0; i < breakages.size(); i++) {
            ObjectNode broken = good.deepCopy();
            breakages.get(i).accept(broken);
            assertFalse("breakage " + i + " passed the schema", JsonSchemaFile.IO_JSON.problems(broken).isEmpty());
        }
    }

    @Test
    public void stringsAreEscapedByTheJsonLibrary() throws IOException {
        for (String f : List.of("intralogistics.bt", "intralogistics.roqme")) {
            Files.copy(Toolchain.ROOT.resolve("examples/intralogistics/" + f), temp.getRoot().toPath().resolve(f));
        }
        String odd = "Cd\\\"Parameter\\\" – \\\\ x";  // in MIRoN source: Cd\"Parameter\" – \\ x
        Path model = temp.getRoot().toPath().resolve("odd.miron");
        Files.writeString(model, "import \"intralogistics.bt\" as main\nimport \"intralogistics.roqme\" as roqme\n\n"
                + "@varpoint speed : number (1:1:2)\n\nin arch {\n  parameterSetRepository \"R\"\n  parameterSet \"" + odd
                + "\"\n  component \"C\"\n  parameter \"p\"\n}\n");
        Path out = temp.newFolder("odd").toPath();
        Toolchain toolchain = new Toolchain();
        assertEquals(toolchain.messages(), 0, toolchain.generate(model.toString(), out.toString()));
        JsonNode io = MAPPER.readTree(out.resolve("odd.io.json").toFile());
        assertEquals(List.of(), JsonSchemaFile.IO_JSON.problems(io));
        assertEquals("Cd\"Parameter\" – \\ x", io.get("varpoints").get(0).get("binding").get("parameterSet").asText());
    }
}
