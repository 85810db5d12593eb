package org.miron.lsp.server;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.eclipse.lsp4j.ExecuteCommandParams;
import org.junit.Rule;
import org.junit.Test;

import com.google.gson.Gson;
import com.google.gson.JsonObject;

/** workspace/executeCommand miron.generate through the client. */
public class GenerateLspTest {
    @Rule
    public final ExampleSession session = new ExampleSession("intralogistics");

    private JsonObject generate(Object... arguments) throws Exception {
        Object answer = session.client.server().getWorkspaceService()
                .executeCommand(new ExecuteCommandParams("miron.generate", List.of(arguments)))
                .get(120, TimeUnit.SECONDS);
        // The session.client's JSON-RPC layer hands over an untyped answer: look at it as JSON again.
        return new Gson().toJsonTree(answer).getAsJsonObject();
    }

    @Test
    public void generatesTheExampleNextToTheModel() throws Exception {
        String uri = session.client.open(session.workspace.resolve("intralogistics.miron"));
        session.client.awaitDiagnostics(uri, d -> true);
        JsonObject result = generate(uri);
        assertTrue(result.toString(), result.get("ok").getAsBoolean());
        Path generated = session.workspace.resolve("generated");
        for (String name : List.of("intralogistics.ext.xml", "intralogistics.mzn", "intralogistics.dzn", "intralogistics.io.json",
                "intralogistics.requirements.json", "intralogistics.roqme.json")) {
            assertTrue(name, Files.isRegularFile(generated.resolve(name)));
            assertTrue(result.toString(), result.get("written").toString().contains(name));
        }
        assertTrue(result.get("message").getAsString(), result.get("message").getAsString().startsWith("Generated 6 files"));
    }

    @Test
    public void aRoqmeModelGeneratesItsRuntimeModel() throws Exception {
        String uri = session.client.open(session.workspace.resolve("intralogistics.roqme"));
        session.client.awaitDiagnostics(uri, d -> true);
        JsonObject result = generate(uri, "roqme-out");
        assertTrue(result.toString(), result.get("ok").getAsBoolean());
        assertTrue(result.get("message").getAsString(),
                result.get("message").getAsString().startsWith("Generated 1 file into "));
        assertTrue(Files.isRegularFile(session.workspace.resolve("roqme-out/intralogistics.roqme.json")));
    }

    @Test
    public void unsavedErrorsStopTheGeneration() throws Exception {
        Path miron = session.workspace.resolve("intralogistics.miron");
        String uri = session.client.open(miron, Files.readString(miron).replace("roqme.safety++", "roqme.safty++"));
        session.client.awaitDiagnostics(uri, IntralogisticsLspTest::hasErrors);
        JsonObject result = generate(uri, "out");
        assertFalse(result.get("ok").getAsBoolean());
        assertTrue(result.get("message").getAsString(), result.get("message").getAsString().contains("safty"));
        assertEquals(0, result.getAsJsonArray("written").size());
        assertFalse(Files.exists(session.workspace.resolve("out")));
    }

    @Test
    public void aBadArgumentIsAnsweredNotThrown() throws Exception {
        JsonObject result = generate("file:///nowhere/model.bt");
        assertFalse(result.get("ok").getAsBoolean());
        assertTrue(result.get("message").getAsString(), result.get("message").getAsString().contains(".miron"));
        JsonObject missing = generate("file:///nowhere/model.miron");
        assertFalse(missing.toString(), missing.get("ok").getAsBoolean());
        assertFalse(generate().get("ok").getAsBoolean());
    }
}
