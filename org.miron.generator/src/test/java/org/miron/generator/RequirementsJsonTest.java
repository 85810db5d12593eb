package org.miron.generator;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.function.Consumer;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.testkit.JsonSchemaFile;

/**
 * The generator's side of name.requirements.json (docs/requirements.md and its schema): the
 * intralogistics example's file is the documented one, valid, and the schema rejects what the
 * monitor could not use.
 */
public class RequirementsJsonTest {
    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    private static final ObjectMapper MAPPER = new ObjectMapper();

    private ObjectNode generate(Path model) throws IOException {
        Path out = temp.newFolder().toPath();
        Toolchain toolchain = new Toolchain();
        assertEquals(toolchain.messages(), 0, toolchain.generate(model.toString(), out.toString()));
        String base = model.getFileName().toString().replaceFirst("\\.miron$", "");
        return (ObjectNode) JsonSchemaFile.REQUIREMENTS.assertValid(out.resolve(base + ".requirements.json"));
    }

    private static JsonNode documented() throws IOException {
        String doc = Files.readString(Toolchain.ROOT.resolve("docs/requirements.md"));
        int start = doc.indexOf("```json\n") + "```json\n".length();
        assertTrue("docs/requirements.md has a ```json example", start > "```json\n".length() - 1);
        return MAPPER.readTree(doc.substring(start, doc.indexOf("```", start)));
    }

    @Test
    public void intralogisticsIsTheDocumentedFile() throws IOException {
        ObjectNode generated = generate(Toolchain.ROOT.resolve("examples/intralogistics/intralogistics.miron"));
        JsonNode doc = documented();
        assertEquals(1, generated.get("format").asInt());
        assertEquals("intralogistics", generated.get("model").asText());
        // the documented requirement, node for node (its state trees are the engine's expression trees)
        assertEquals(normalised(doc.get("requirements").get(0)), normalised(generated.get("requirements").get(0)));
        List<String> names = List.of("docksOnLowBattery", "neverStranded", "slowNearPeople", "slowSoonNearPeople",
                "rarelyStranded");
        for (int i = 0; i < names.size(); i++) {
            assertEquals(names.get(i), generated.get("requirements").get(i).get("name").asText());
        }
        assertEquals(0.9, generated.get("requirements").get(4).get("probability").asDouble(), 0);
        // each documented signal the example reads is described as documented (the doc abbreviates maxVelocity's values)
        for (JsonNode signal : doc.get("signals")) {
            JsonNode mine = null;
            for (JsonNode s : generated.get("signals")) {
                if (s.get("name").equals(signal.get("name"))) {
                    mine = s;
                }
            }
            if (signal.get("name").asText().equals("roqme.FreeSpace")) {
                assertEquals("no requirement reads FreeSpace", null, mine);
                continue;
            }
            ObjectNode expected = signal.deepCopy();
            ObjectNode actual = ((ObjectNode) mine).deepCopy();
            if (expected.get("name").asText().equals("maxVelocity")) {
                expected.remove("values");
                actual.remove("values");
            }
            assertEquals(expected, actual);
        }
        assertEquals("every signal once", 6, generated.get("signals").size());
    }

    /** Numbers compared as numbers (the doc writes 1, the engine's trees 1.0). */
    private static JsonNode normalised(JsonNode n) throws IOException {
        return MAPPER.readTree(n.toString().replaceAll("(\\d)\\.0([,}\\]])", "$1$2"));
    }

    @Test
    public void documentedExampleIsValid() throws IOException {
        assertEquals(List.of(), JsonSchemaFile.REQUIREMENTS.problems(documented()));
    }

    @Test
    public void hospitalRequirementsAreWritten() throws IOException {
        ObjectNode json = generate(Toolchain.ROOT.resolve("examples/hospital-delivery/hospital.miron"));
        JsonNode charges = json.get("requirements").get(1);
        assertEquals("chargesWhenLow", charges.get("name").asText());
        assertEquals(1_800_000, charges.at("/formula/args/0/args/1/within").asLong());
        assertEquals("[\"qos.lowBattery\",\"preparation\"]", charges.get("reads").toString());
        assertTrue(json.get("requirements").get(2).get("probability").isNumber());
    }

    @Test
    public void aModelWithoutRequirementsGetsEmptyLists() throws IOException {
        Path dir = temp.newFolder("plain").toPath();
        Path roqme = Files.writeString(dir.resolve("plain.roqme"), "roqme Plain\ncontext level : number (0:10)\nproperty ok\n");
        Path model = Files.writeString(dir.resolve("plain.miron"), "import \"plain.roqme\" as q\n"
                + "@varpoint v : number (0:1:3) in arch { parameterSetRepository \"R\" parameterSet \"S\" component \"C\" parameter \"p\" }\n"
                + "rule r : q.level > 5 implies v = 1\n");
        assertTrue(Files.exists(roqme));
        ObjectNode json = generate(model);
        assertEquals(0, json.get("signals").size());
        assertEquals(0, json.get("requirements").size());
    }

    @Test
    public void schemaRejectsWhatTheMonitorCannotUse() throws IOException {
        ObjectNode good = generate(Toolchain.ROOT.resolve("examples/intralogistics/intralogistics.miron"));
        List<Consumer<ObjectNode>> breakages = List.of(
                j -> j.remove("signals"),
                j -> j.put("format", 2),
                j -> ((ObjectNode) j.at("/requirements/0/formula")).put("op", "until"),
                j -> ((ObjectNode) j.at("/requirements/0/formula/args/0/args/1")).put("within", 0),
                j -> ((ObjectNode) j.at("/requirements/0/formula/args/0/args/0")).remove("reads"),
                j -> ((ObjectNode) j.at("/requirements/3")).put("probability", 1),
                j -> ((ObjectNode) j.at("/requirements/0")).remove("line"),
                j -> ((ObjectNode) j.at("/signals/0")).put("kind", "metric"),
                j -> ((ObjectNode) j.at("/signals/2")).remove("roqmeType"));
        for (int i = 0; i < breakages.size(); i++) {
            ObjectNode broken = good.deepCopy();
            breakages.get(i).accept(broken);
            assertFalse("breakage " + i + " passed the schema", JsonSchemaFile.REQUIREMENTS.problems(broken).isEmpty());
        }
    }

    @Test
    public void stateExpressionsAreIoJsonExpressions() throws IOException {
        JsonNode io = MAPPER.readTree(JsonSchemaFile.IO_JSON.file().toFile()).at("/$defs/expression");
        ObjectNode req = (ObjectNode) MAPPER.readTree(JsonSchemaFile.REQUIREMENTS.file().toFile()).at("/$defs/expression").deepCopy();
        ObjectNode ioCopy = ((ObjectNode) io).deepCopy();
        req.remove("description");
        ioCopy.remove("description");
        assertEquals("requirements.schema.json's expression is io-json.schema.json's", ioCopy, req);
    }
}
