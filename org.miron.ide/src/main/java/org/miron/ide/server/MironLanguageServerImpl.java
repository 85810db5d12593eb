package org.miron.ide.server;

import java.util.List;
import java.util.concurrent.CompletableFuture;

import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializeResult;
import org.eclipse.lsp4j.WorkspaceClientCapabilities;
import org.eclipse.xtext.ide.server.LanguageServerImpl;

/** Xtext's language server, also for clients that open single files without any workspace folder. */
public class MironLanguageServerImpl extends LanguageServerImpl {

    // Without a root Xtext would fail in initialize; an empty list of workspace folders works.
    @Override
    public CompletableFuture<InitializeResult> initialize(InitializeParams params) {
        if (params.getRootUri() == null && params.getRootPath() == null && params.getWorkspaceFolders() == null) {
            params.setWorkspaceFolders(List.of());
            if (params.getCapabilities() == null) {
                params.setCapabilities(new ClientCapabilities());
            }
            if (params.getCapabilities().getWorkspace() == null) {
                params.getCapabilities().setWorkspace(new WorkspaceClientCapabilities());
            }
            params.getCapabilities().getWorkspace().setWorkspaceFolders(true);
        }
        return super.initialize(params);
    }
}
