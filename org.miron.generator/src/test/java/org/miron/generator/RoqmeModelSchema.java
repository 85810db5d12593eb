package org.miron.generator;

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

/** docs/roqme-model.schema.json, the runtime model's contract with the provider, as a validator for tests. */
final class RoqmeModelSchema {
    static final Path FILE = Toolchain.ROOT.resolve("docs/roqme-model.schema.json");
    private static final ObjectMapper MAPPER = new ObjectMapper();
    private static Schema schema;

    private RoqmeModelSchema() {
    }

    private static synchronized Schema schema() {
        if (schema == null) {
            try (InputStream in = Files.newInputStream(FILE)) {
                schema = SchemaRegistry.withDefaultDialect(SpecificationVersion.DRAFT_2020_12).getSchema(in);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        return schema;
    }

    /** What the schema finds wrong with json (empty when it is valid). */
    static List<String> problems(JsonNode json) {
        return schema().validate(json).stream().map(Object::toString).toList();
    }

    /** Reads a generated file and asserts it follows the schema. */
    static JsonNode read(Path file) throws IOException {
        JsonNode json = MAPPER.readTree(Files.readString(file));
        List<String> problems = problems(json);
        assertTrue(file + " breaks " + FILE.getFileName() + ": " + problems, problems.isEmpty());
        return json;
    }
}
