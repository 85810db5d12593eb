package org.miron.lsp.server;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertNull;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializedParams;
import org.eclipse.lsp4j.WorkspaceFolder;
import org.eclipse.emf.common.util.URI;
import org.junit.After;
import org.junit.Before;
import org.junit.Test;
import org.miron.testkit.Examples;
import org.miron.testkit.Folders;
import org.miron.testkit.lsp.LspClient;

/**
 * Issue 23, item 1: the server indexes only folders it understood. Neovim's documented root of a
 * relative file name sent "file://." and the server scanned "/" without ever answering initialize.
 */
public class WorkspaceRootLspTest {
    private Path workspace;

    @Before
    public void copy() throws Exception {
        workspace = Examples.copy("intralogistics");
    }

    @After
    public void delete() throws Exception {
        Folders.delete(workspace);
    }

    /** initialize with a root the server must refuse, then the example opened as a single file. */
    private void refusedRootThenOpenedFileFolderServes(InitializeParams params) throws Exception {
        try (LspClient client = new LspClient()) {
            client.server().initialize(params).get(60, TimeUnit.SECONDS);
            client.server().initialized(new InitializedParams());
            String miron = client.open(workspace.resolve("intralogistics.miron"));
            client.awaitDiagnostics(miron, d -> !IntralogisticsLspTest.hasErrors(d));
            // The opened file's folder became the workspace: its .bt, never opened, was built too.
            String bt = LspClient.uri(workspace.resolve("intralogistics.bt"));
            client.awaitDiagnostics(bt, d -> true);
        }
    }

    @Test
    public void aRelativeRootUriIsRefused() throws Exception {
        InitializeParams params = new InitializeParams();
        params.setRootUri("file://.");
        refusedRootThenOpenedFileFolderServes(params);
    }

    @Test
    public void aRelativeRootPathIsRefused() throws Exception {
        InitializeParams params = new InitializeParams();
        params.setRootPath(".");
        refusedRootThenOpenedFileFolderServes(params);
    }

    @Test
    public void theFileSystemRootAndOtherSchemesAreRefused() throws Exception {
        InitializeParams params = new InitializeParams();
        params.setWorkspaceFolders(List.of(new WorkspaceFolder("file:///", "root"),
                new WorkspaceFolder("untitled:folder", "odd"), new WorkspaceFolder("file://host/share", "remote")));
        refusedRootThenOpenedFileFolderServes(params);
    }

    @Test
    public void buildOutputsPackageCachesAndHiddenFoldersAreNotIndexed() throws Exception {
        String broken = "roqme Broken\ncontext C : nosuchtype\n";
        List<String> skipped = new ArrayList<>();
        for (String folder : List.of("build", "node_modules", ".cache", "sub/target")) {
            Path file = workspace.resolve(folder).resolve("broken.roqme");
            Files.createDirectories(file.getParent());
            Files.writeString(file, broken);
            skipped.add(LspClient.uri(file));
        }
        Path indexed = workspace.resolve("sub/models/broken.roqme");
        Files.createDirectories(indexed.getParent());
        Files.writeString(indexed, broken);
        try (LspClient client = new LspClient()) {
            client.initialize(workspace);
            // The initial build publishes the errors of every file it indexed, never opened or not.
            client.awaitDiagnostics(LspClient.uri(indexed), IntralogisticsLspTest::hasErrors);
            String miron = client.open(workspace.resolve("intralogistics.miron"));
            client.awaitDiagnostics(miron, d -> !IntralogisticsLspTest.hasErrors(d));
            for (String uri : skipped) {
                assertNull(uri, client.published(uri));
            }
        }
    }

    @Test
    public void theScanStopsAtItsLimit() throws Exception {
        for (int i = 0; i < 30; i++) {
            Files.writeString(workspace.resolve("m" + i + ".roqme"), "roqme M" + i + "\n");
        }
        List<URI> found = new ArrayList<>();
        new BoundedFileSystemScanner(10).scan(URI.createFileURI(workspace.toString()), found::add);
        assertFalse(found.isEmpty());
        assertTrue(found.toString(), found.size() < 10);
        List<URI> all = new ArrayList<>();
        new BoundedFileSystemScanner().scan(URI.createFileURI(workspace.toString()), all::add);
        // every model file: the 30 and the example's three (whatever else the example folder holds)
        assertEquals(all.toString(), 30 + 3, all.stream().map(URI::fileExtension)
                .filter(e -> List.of("roqme", "miron", "bt").contains(e)).count());
    }
}
