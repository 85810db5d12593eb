package org.miron.runtime.engine;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.fail;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import com.networknt.schema.Schema;
import com.networknt.schema.SchemaRegistry;
import com.networknt.schema.SpecificationVersion;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import org.junit.BeforeClass;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * The engine's side of the io.json contract (docs/io-json.schema.json, the schema the generator's
 * tests hold generated files to): the engine's test models follow it, and files that break it in
 * ways the engine cannot use are refused when loading.
 */
public class IoContractTest {
    private static final Path ROOT = Path.of(System.getProperty("miron.root", "..")).toAbsolutePath().normalize();
    private static final ObjectMapper MAPPER = new ObjectMapper();
    private static Schema schema;

    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();

    @BeforeClass
    public static void loadSchema() throws IOException {
        try (InputStream in = Files.newInputStream(ROOT.resolve("docs/io-json.schema.json"))) {
            schema = SchemaRegistry.withDefaultDialect(SpecificationVersion.DRAFT_2020_12).getSchema(in);
        }
    }

    private static List<String> problems(JsonNode json) {
        return schema.validate(json).stream().map(Object::toString).toList();
    }

    /** The model's .io.json, .mzn and .dzn copied to the temporary folder; returns the io.json. */
    private Path copy(String model) throws IOException {
        Path dir = tmp.getRoot().toPath();
        for (String ext : List.of(".io.json", ".mzn", ".dzn")) {
            try (InputStream in = IoContractTest.class.getResourceAsStream("/models/" + model + ext)) {
                Files.copy(in, dir.resolve(model + ext), StandardCopyOption.REPLACE_EXISTING);
            }
        }
        return dir.resolve(model + ".io.json");
    }

    @Test
    public void testModelsFollowTheSchema() throws IOException {
        for (String model : List.of("testbot", "portbot")) {
            Path io = copy(model);
            assertEquals(model, List.of(), problems(MAPPER.readTree(io.toFile())));
            assertEquals(model, IoModel.load(io).model());
        }
    }

    private static ObjectNode varpoint(ObjectNode io, int i) {
        return (ObjectNode) io.get("varpoints").get(i);
    }

    @Test
    public void filesBreakingTheSchemaAreRefused() throws IOException {
        Path good = copy("testbot");
        ObjectNode original = (ObjectNode) MAPPER.readTree(good.toFile());
        Map<String, Consumer<ObjectNode>> breakages = new LinkedHashMap<>();
        breakages.put("no decision", io -> varpoint(io, 0).remove("decision"));
        breakages.put("unknown varpoint kind", io -> varpoint(io, 0).put("kind", "set"));
        breakages.put("no values", io -> varpoint(io, 0).putArray("values"));
        breakages.put("a number among enum labels", io -> ((ArrayNode) varpoint(io, 0).get("values")).add(3));
        breakages.put("a label among numbers", io -> ((ArrayNode) varpoint(io, 1).get("values")).add("fast"));
        breakages.put("negative preset", io -> varpoint(io, 0).put("preset", -1));
        breakages.put("unknown input kind", io -> ((ObjectNode) io.get("inputs").get(0)).put("kind", "clock"));
        breakages.put("unknown input type", io -> ((ObjectNode) io.get("inputs").get(0)).put("type", "string"));
        breakages.put("context without known flag", io -> ((ObjectNode) io.get("inputs").get(2)).remove("known"));
        breakages.put("no mzn", io -> io.remove("mzn"));
        breakages.put("format 2", io -> io.put("format", 2));
        breakages.put("binding without type", io -> ((ObjectNode) varpoint(io, 0).get("binding")).remove("type"));
        Path bad = tmp.getRoot().toPath().resolve("bad.io.json");
        for (Map.Entry<String, Consumer<ObjectNode>> breakage : breakages.entrySet()) {
            ObjectNode broken = original.deepCopy();
            breakage.getValue().accept(broken);
            assertFalse(breakage.getKey() + " passed the schema", problems(broken).isEmpty());
            Files.writeString(bad, MAPPER.writeValueAsString(broken));
            try {
                IoModel.load(bad);
                fail(breakage.getKey() + ": the engine loaded a file breaking the contract");
            } catch (IllegalArgumentException expected) {
                // refused, with the file named
            }
        }
    }
}
