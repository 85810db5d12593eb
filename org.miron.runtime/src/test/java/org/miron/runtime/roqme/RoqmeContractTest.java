package org.miron.runtime.roqme;

import static org.junit.Assert.assertEquals;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.List;
import org.junit.Test;
import org.miron.runtime.Json;
import org.miron.testkit.JsonSchemaFile;

/**
 * The provider's side of the runtime-model contract: the hand-written models its tests run follow
 * docs/roqme-model.schema.json, the schema the generator's tests hold generated files to (the test kit's
 * JsonSchemaFile).
 */
public class RoqmeContractTest {
    @Test
    public void testModelsFollowTheSchema() throws Exception {
        for (String model : List.of("worked.roqme.json", "intralogistics.roqme.json")) {
            JsonNode json = Json.MAPPER.readTree(RoqmeFixtures.resource(model));
            assertEquals(model, List.of(), JsonSchemaFile.ROQME_MODEL.problems(json));
            RoqmeFixtures.compile(RoqmeFixtures.resource(model)); // and the provider runs it
        }
    }
}
