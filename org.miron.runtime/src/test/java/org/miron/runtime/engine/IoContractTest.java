package org.miron.runtime.engine;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.fail;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.testkit.JsonSchemaFile;
import org.miron.testkit.runtime.TestModels;

/**
 * The engine's side of the io.json contract (docs/io-json.schema.json, the schema the generator's
 * tests hold generated files to): the engine's test models follow it, and files that break it in
 * ways the engine cannot use are refused when loading.
 */
public class IoContractTest {
    private static final ObjectMapper MAPPER = new ObjectMapper();

    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();

    private static List<String> problems(JsonNode json) {
        return JsonSchemaFile.IO_JSON.problems(json);
    }

    /** The model's .io.json, .mzn and .dzn copied to the temporary folder; returns the io.json. */
    private Path copy(String model) throws IOException {
        return TestModels.copy(model, tmp.getRoot().toPath());
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

    /**
     * Files breaking the schema that the engine once loaded anyway (and then misbehaved on): each
     * is refused, and the message names the file and where in it the problem is.
     */
    @Test
    public void schemaBreakingFilesAreRefusedNamingTheField() throws IOException {
        Path good = copy("testbot");
        ObjectNode original = (ObjectNode) MAPPER.readTree(good.toFile());
        Map<String, Consumer<ObjectNode>> breakages = new LinkedHashMap<>();
        Map<String, String> named = new LinkedHashMap<>();
        breakages.put("unknown binding type", io -> ((ObjectNode) varpoint(io, 0).get("binding")).put("type", "plugin"));
        named.put("unknown binding type", "varpoints[0].binding: field 'type'");
        breakages.put("bt binding without variable", io -> ((ObjectNode) varpoint(io, 0).get("binding")).remove("variable"));
        named.put("bt binding without variable", "varpoints[0].binding: missing field 'variable'");
        breakages.put("arch binding without parameter", io -> ((ObjectNode) varpoint(io, 1).get("binding")).remove("parameter"));
        named.put("arch binding without parameter", "varpoints[1].binding: missing field 'parameter'");
        breakages.put("no inputs", io -> io.remove("inputs"));
        named.put("no inputs", "missing field 'inputs'");
        breakages.put("no varpoints", io -> io.remove("varpoints"));
        named.put("no varpoints", "missing field 'varpoints'");
        breakages.put("inputs as an object", io -> io.putObject("inputs").set("0", original.get("inputs").get(0).deepCopy()));
        named.put("inputs as an object", "field 'inputs'");
        breakages.put("enum context without literals", io -> ((ObjectNode) io.get("inputs").get(3)).remove("literals"));
        named.put("enum context without literals", "inputs[3]: missing field 'literals'");
        breakages.put("unknown roqmeType", io -> ((ObjectNode) io.get("inputs").get(2)).put("roqmeType", "colour"));
        named.put("unknown roqmeType", "inputs[2]: field 'roqmeType'");
        breakages.put("fractional preset", io -> varpoint(io, 0).put("preset", 1.5));
        named.put("fractional preset", "varpoints[0]: field 'preset'");
        breakages.put("int metric", io -> ((ObjectNode) io.get("inputs").get(0)).put("type", "int"));
        named.put("int metric", "inputs[0]: field 'type'");
        breakages.put("initial outside [0,1]", io -> ((ObjectNode) io.get("inputs").get(0)).put("initial", 2));
        named.put("initial outside [0,1]", "inputs[0]: field 'initial'");
        breakages.put("decision not an identifier", io -> varpoint(io, 0).put("decision", "task-var"));
        named.put("decision not an identifier", "varpoints[0]: field 'decision'");
        breakages.put("rule keep not an identifier",
                io -> io.putArray("rules").addObject().put("name", "battery").put("keep", "keep-1"));
        named.put("rule keep not an identifier", "rules[0]: field 'keep'");
        breakages.put("boolean varpoint as numbers", io -> varpoint(io, 1).put("kind", "boolean"));
        named.put("boolean varpoint as numbers", "varpoints[1]: varpoint maxVelocity (boolean) has values");
        breakages.put("boolean varpoint as 0 and 1", io -> {
            varpoint(io, 1).put("kind", "boolean");
            varpoint(io, 1).putArray("values").add(0).add(1);
        });
        named.put("boolean varpoint as 0 and 1", "not [false,true]");
        Path bad = tmp.getRoot().toPath().resolve("bad.io.json");
        List<String> wrong = new ArrayList<>();
        for (Map.Entry<String, Consumer<ObjectNode>> breakage : breakages.entrySet()) {
            String name = breakage.getKey();
            ObjectNode broken = original.deepCopy();
            breakage.getValue().accept(broken);
            assertFalse(name + " passed the schema", problems(broken).isEmpty());
            Files.writeString(bad, MAPPER.writeValueAsString(broken));
            try {
                IoModel.load(bad);
                wrong.add(name + ": the engine loaded a file breaking the contract");
            } catch (IllegalArgumentException e) {
                if (!e.getMessage().startsWith(bad + ": ") || !e.getMessage().contains(named.get(name))) {
                    wrong.add(name + ": message does not name the file and '" + named.get(name) + "': " + e.getMessage());
                }
            }
        }
        assertEquals(String.join("\n", wrong), List.of(), wrong);
    }
}
