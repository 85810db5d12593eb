package org.miron.testkit;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assert.fail;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/** The one way tests find the repository root, on real folders. */
public class RepositoryRootTest {
    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    @Test
    public void theBuildsPropertyNamesTheCheckout() {
        Path root = RepositoryRoot.path();
        assertTrue(Files.isRegularFile(root.resolve("settings.gradle")));
        assertTrue(Files.isDirectory(RepositoryRoot.resolve("org.miron.testkit")));
        assertEquals(root, Path.of(System.getProperty("miron.root")).toAbsolutePath().normalize());
    }

    @Test
    public void withoutThePropertyTheNearestFolderWithSettingsGradleAboveTheStartIsTheRoot() throws IOException {
        Path root = temp.newFolder("checkout").toPath();
        Files.writeString(root.resolve("settings.gradle"), "");
        Path module = Files.createDirectories(root.resolve("org.miron.x/src"));
        assertEquals(root, RepositoryRoot.find(null, module));
        assertEquals(root, RepositoryRoot.find(null, root));
    }

    @Test
    public void aPropertyNotNamingACheckoutIsAnErrorSayingSo() throws IOException {
        Path elsewhere = temp.newFolder("elsewhere").toPath();
        try {
            RepositoryRoot.find(elsewhere.toString(), elsewhere);
            fail("accepted " + elsewhere);
        } catch (IllegalStateException e) {
            assertTrue(e.getMessage(), e.getMessage().contains("miron.root=" + elsewhere) && e.getMessage().contains("settings.gradle"));
        }
    }

    @Test
    public void noRootAnywhereIsAnErrorNamingWhereItLooked() throws IOException {
        Path outside = temp.newFolder("no", "checkout").toPath();
        // a temporary folder may itself sit below a checkout: only assert when none is above it
        for (Path dir = outside; dir != null; dir = dir.getParent()) {
            if (Files.exists(dir.resolve("settings.gradle"))) {
                return;
            }
        }
        try {
            RepositoryRoot.find(null, outside);
            fail("found a root above " + outside);
        } catch (IllegalStateException e) {
            assertTrue(e.getMessage(), e.getMessage().contains(outside.toString()) && e.getMessage().contains("miron.root"));
        }
    }
}
