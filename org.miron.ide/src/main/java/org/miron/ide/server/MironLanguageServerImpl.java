package org.miron.ide.server;

import java.util.List;
import java.util.concurrent.CompletableFuture;

import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.ExecuteCommandCapabilities;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializeResult;
import org.eclipse.lsp4j.ServerCapabilities;
import org.eclipse.lsp4j.WorkspaceClientCapabilities;
import org.eclipse.xtext.ide.server.LanguageServerImpl;

/**
 * Xtext's language server, also for clients that open single files without any workspace folder
 * and for clients that do not announce workspace/executeCommand (miron.generate is then still
 * offered: Xtext would leave its command registry uninitialized and fail on the first command).
 */
public class MironLanguageServerImpl extends LanguageServerImpl {
    private static final List<String> TRIGGER_CHARACTERS = List.of(".", ":", "<", "\"");

    @Override
    public CompletableFuture<InitializeResult> initialize(InitializeParams params) {
        if (params.getCapabilities() == null) {
            params.setCapabilities(new ClientCapabilities());
        }
        if (params.getCapabilities().getWorkspace() == null) {
            params.getCapabilities().setWorkspace(new WorkspaceClientCapabilities());
        }
        WorkspaceClientCapabilities workspace = params.getCapabilities().getWorkspace();
        if (workspace.getExecuteCommand() == null) {
            workspace.setExecuteCommand(new ExecuteCommandCapabilities(false));
        }
        // Without a root Xtext would fail in initialize; an empty list of workspace folders works.
        if (params.getRootUri() == null && params.getRootPath() == null && params.getWorkspaceFolders() == null) {
            params.setWorkspaceFolders(List.of());
            workspace.setWorkspaceFolders(true);
        }
        return super.initialize(params);
    }

    // Completion also starts where the three languages want it: '<' and '"' in BT, '::' in MIRoN.
    @Override
    protected ServerCapabilities createServerCapabilities(InitializeParams params) {
        ServerCapabilities capabilities = super.createServerCapabilities(params);
        if (capabilities.getCompletionProvider() != null) {
            capabilities.getCompletionProvider().setTriggerCharacters(TRIGGER_CHARACTERS);
        }
        return capabilities;
    }
}
