package org.miron.runtime.sim;

import static org.junit.Assert.assertFalse;

import java.nio.file.Files;
import org.junit.Test;
import org.miron.testkit.JsonSchemaFile;
import org.miron.testkit.RepositoryRoot;

/** The example worlds follow docs/world.schema.json, and the schema is strict enough to refuse a misspelt field. */
public class WorldSchemaTest {
    @Test
    public void theExampleWorldsFollowTheSchema() throws Exception {
        JsonSchemaFile.WORLD.assertValid(RepositoryRoot.resolve("examples/intralogistics/world.json"));
        JsonSchemaFile.WORLD.assertValid(RepositoryRoot.resolve("examples/hospital-delivery/world.json"));
        JsonSchemaFile.WORLD.assertValid(RepositoryRoot.resolve("examples/nav2/world.json"));
    }

    @Test
    public void aMisspeltFieldBreaksIt() throws Exception {
        String world = Files.readString(RepositoryRoot.resolve("examples/intralogistics/world.json"))
                .replace("\"perSecond\": {\n        \"battery\"", "\"perSeconds\": {\n        \"battery\"");
        assertFalse(world.contains("\"perSecond\": {\n        \"battery\""));
        assertFalse(JsonSchemaFile.WORLD.problems(world).isEmpty());
    }
}
