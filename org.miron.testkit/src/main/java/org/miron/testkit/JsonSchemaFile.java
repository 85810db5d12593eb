package org.miron.testkit;

import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.networknt.schema.Schema;
import com.networknt.schema.SchemaRegistry;
import com.networknt.schema.SpecificationVersion;

/**
 * A JSON Schema of docs/ as a validator, so the generator's tests (what it writes) and the
 * runtime's (what it reads) hold files to the same contract. Needs the JSON Schema validator and
 * Jackson on the test class path: the modules using it declare them.
 */
public final class JsonSchemaFile {
    /** docs/io-json.schema.json: the generator ⇄ engine contract. */
    public static final JsonSchemaFile IO_JSON = new JsonSchemaFile("docs/io-json.schema.json");
    /** docs/requirements.schema.json: the generator ⇄ requirement monitor contract. */
    public static final JsonSchemaFile REQUIREMENTS = new JsonSchemaFile("docs/requirements.schema.json");
    /** docs/roqme-model.schema.json: the RoQME runtime model's contract with the provider. */
    public static final JsonSchemaFile ROQME_MODEL = new JsonSchemaFile("docs/roqme-model.schema.json");
    /** docs/world.schema.json: the structure of a world file for `miron simulate`. */
    public static final JsonSchemaFile WORLD = new JsonSchemaFile("docs/world.schema.json");
    /** docs/dds-bridge.schema.json: the configuration of {@code miron dds-bridge}. */
    public static final JsonSchemaFile DDS_BRIDGE = new JsonSchemaFile("docs/dds-bridge.schema.json");
    /** What `miron verify` writes into OUT/summary.json. */
    public static final JsonSchemaFile VERIFY_SUMMARY = new JsonSchemaFile("docs/verify-summary.schema.json");

    private static final ObjectMapper MAPPER = new ObjectMapper();
    private final String relative;
    private Schema schema;

    private JsonSchemaFile(String relative) {
        this.relative = relative;
    }

    /** The schema file. */
    public Path file() {
        return RepositoryRoot.resolve(relative);
    }

    private synchronized Schema schema() {
        if (schema == null) {
            try (InputStream in = Files.newInputStream(file())) {
                schema = SchemaRegistry.withDefaultDialect(SpecificationVersion.DRAFT_2020_12).getSchema(in);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        return schema;
    }

    /** What the schema finds wrong with json (empty when it is valid). */
    public List<String> problems(JsonNode json) {
        return schema().validate(json).stream().map(Object::toString).toList();
    }

    /** The same for JSON text. */
    public List<String> problems(String json) {
        try {
            return problems(MAPPER.readTree(json));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** Reads a file and asserts it follows the schema; returns its JSON. */
    public JsonNode assertValid(Path json) throws IOException {
        JsonNode node = MAPPER.readTree(Files.readString(json));
        List<String> problems = problems(node);
        assertTrue(json + " breaks " + file().getFileName() + ": " + problems, problems.isEmpty());
        return node;
    }
}
