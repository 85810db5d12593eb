package org.miron.lsp.server;

import java.nio.file.Path;

import org.junit.rules.ExternalResource;
import org.miron.testkit.Examples;
import org.miron.testkit.Folders;
import org.miron.testkit.lsp.LspClient;

/**
 * A test's own copy of an example folder with an LSP client initialized on it, closed and deleted
 * after the test: the set-up most LSP tests share.
 */
public final class ExampleSession extends ExternalResource {
    private final String example;
    Path workspace;
    LspClient client;

    public ExampleSession(String example) {
        this.example = example;
    }

    @Override
    protected void before() throws Throwable {
        workspace = Examples.copy(example);
        client = new LspClient();
        client.initialize(workspace);
    }

    @Override
    protected void after() {
        try {
            client.close();
            Folders.delete(workspace);
        } catch (Exception e) {
            throw new IllegalStateException("cannot tear down the LSP session on " + workspace, e);
        }
    }
}
