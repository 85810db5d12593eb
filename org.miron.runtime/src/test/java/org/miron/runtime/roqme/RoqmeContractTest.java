package org.miron.runtime.roqme;

import static org.junit.Assert.assertEquals;

import com.fasterxml.jackson.databind.JsonNode;
import com.networknt.schema.Schema;
import com.networknt.schema.SchemaRegistry;
import com.networknt.schema.SpecificationVersion;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.Assume;
import org.junit.Test;
import org.miron.runtime.Json;

/**
 * The provider's side of the runtime-model contract: the hand-written models its tests run follow
 * docs/roqme-model.schema.json, the schema the generator's tests hold generated files to. The schema
 * comes with the generator's side (issue 22, item 2); without it there is nothing to check against.
 */
public class RoqmeContractTest {
    private static final Path ROOT = Path.of(System.getProperty("miron.root", "..")).toAbsolutePath().normalize();

    @Test
    public void testModelsFollowTheSchema() throws Exception {
        Path file = ROOT.resolve("docs/roqme-model.schema.json");
        Assume.assumeTrue("no " + file, Files.exists(file));
        Schema schema;
        try (InputStream in = Files.newInputStream(file)) {
            schema = SchemaRegistry.withDefaultDialect(SpecificationVersion.DRAFT_2020_12).getSchema(in);
        }
        for (String model : List.of("worked.roqme.json", "intralogistics.roqme.json")) {
            JsonNode json = Json.MAPPER.readTree(RoqmeFixtures.resource(model));
            assertEquals(model, List.of(), schema.validate(json).stream().map(Object::toString).toList());
            RoqmeFixtures.compile(RoqmeFixtures.resource(model)); // and the provider runs it
        }
    }
}
