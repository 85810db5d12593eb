package org.miron.testkit;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/** Copying and deleting trees, and the examples' copies built on it. */
public class FoldersTest {
    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    @Test
    public void copiesAndDeletesWholeTrees() throws IOException {
        Path from = temp.newFolder("from").toPath();
        Files.createDirectories(from.resolve("a/b"));
        Files.writeString(from.resolve("a/b/c.txt"), "c");
        Files.writeString(from.resolve("top.txt"), "top");
        Path to = Folders.copy(from, temp.getRoot().toPath().resolve("to"));
        assertEquals("c", Files.readString(to.resolve("a/b/c.txt")));
        assertEquals("top", Files.readString(to.resolve("top.txt")));
        Folders.delete(to);
        assertFalse(Files.exists(to));
        assertTrue(Files.exists(from.resolve("a/b/c.txt")));
    }

    @Test
    public void anExampleCopyHoldsTheExamplesFiles() throws IOException {
        Path copy = Examples.copy("intralogistics");
        try {
            assertEquals(Files.readString(RepositoryRoot.resolve("examples/intralogistics/intralogistics.miron")),
                    Files.readString(copy.resolve("intralogistics.miron")));
        } finally {
            Folders.delete(copy);
        }
        assertFalse(Files.exists(copy));
    }
}
