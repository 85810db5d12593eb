package org.miron.generator.standalone;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.util.List;

import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * A build tool (the Gradle plugin) names files relative to its project folder, whatever the JVM's
 * working directory, and checks files as `miron check` does.
 */
public class ModelLoaderBaseFolderTest {
    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    private File brokenTree() throws IOException {
        File file = new File(temp.newFolder("project", "models"), "broken.bt");
        Files.writeString(file.toPath(), "<root main_tree_to_execute=\"M\">\n  <BehaviorTree ID=\"M\">\n"
                + "    <Inverter/>\n  </BehaviorTree>\n</root>\n");
        return file;
    }

    @Test
    public void diagnosticsNameFilesRelativeToTheBaseFolder() throws IOException {
        File tree = brokenTree();
        List<Diagnostic> diagnostics = new ModelLoader(temp.getRoot().toPath().resolve("project")).check(List.of(tree));
        assertTrue(ModelLoader.hasErrors(diagnostics));
        assertEquals(diagnostics.toString(), "models/broken.bt:3:6: error [bt.decorator-child-count]: "
                + "Inverter needs exactly one child, it has none", diagnostics.get(0).toString());
    }

    @Test
    public void filesOutsideTheBaseFolderKeepTheirAbsolutePath() throws IOException {
        File tree = brokenTree();
        List<Diagnostic> diagnostics = new ModelLoader(temp.newFolder("elsewhere").toPath()).check(List.of(tree));
        assertEquals(tree.getAbsolutePath(), diagnostics.get(0).file());
    }

    @Test
    public void warningsAreNoErrors() {
        assertFalse(ModelLoader.hasErrors(List.of(new Diagnostic("a.bt", 1, 1, Diagnostic.Severity.WARNING, "w"))));
    }
}
