package org.miron.lsp.server;

import java.util.List;
import java.util.Map;
import java.util.function.BiConsumer;
import java.util.function.Supplier;
import java.util.concurrent.CompletableFuture;

import org.eclipse.lsp4j.ClientCapabilities;
import org.eclipse.lsp4j.CompletionItem;
import org.eclipse.lsp4j.CompletionList;
import org.eclipse.lsp4j.CompletionParams;
import org.eclipse.lsp4j.DefinitionParams;
import org.eclipse.lsp4j.DidChangeWorkspaceFoldersParams;
import org.eclipse.lsp4j.DidOpenTextDocumentParams;
import org.eclipse.lsp4j.DocumentHighlight;
import org.eclipse.lsp4j.DocumentHighlightParams;
import org.eclipse.lsp4j.ExecuteCommandCapabilities;
import org.eclipse.lsp4j.Hover;
import org.eclipse.lsp4j.HoverParams;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializeResult;
import org.eclipse.lsp4j.InitializedParams;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.ReferenceParams;
import org.eclipse.lsp4j.RenameParams;
import org.eclipse.lsp4j.WorkspaceEdit;
import org.eclipse.lsp4j.ServerCapabilities;
import org.eclipse.lsp4j.WorkspaceClientCapabilities;
import org.eclipse.lsp4j.jsonrpc.json.JsonRpcMethod;
import org.eclipse.lsp4j.jsonrpc.services.ServiceEndpoints;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.eclipse.lsp4j.jsonrpc.services.JsonNotification;
import org.eclipse.xtext.ide.server.BuildManager;
import org.eclipse.xtext.ide.server.LanguageServerImpl;
import org.eclipse.xtext.ide.server.UriExtensions;
import org.eclipse.xtext.ide.server.hover.IHoverService;
import org.eclipse.xtext.util.CancelIndicator;

import org.miron.lsp.diagram.DiagramGeneration;
import org.miron.lsp.diagram.DiagramServers;

import com.google.gson.JsonObject;
import com.google.inject.Inject;

/**
 * Xtext's language server, also for clients that open single files without any workspace folder
 * and for clients that do not announce workspace/executeCommand (miron.generate is then still
 * offered: Xtext would leave its command registry uninitialized and fail on the first command),
 * and answering requests for positions outside the document.
 */
public class MironLanguageServerImpl extends LanguageServerImpl {
    private static final List<String> TRIGGER_CHARACTERS = List.of(".", ":", "<", "\"");
    private final WorkspaceFolderSet folders = new WorkspaceFolderSet();
    private final FileChangeSource fileChanges = new FileChangeSource(this::didChangeWatchedFiles);
    /**
     * Made on the first diagram message: Sprotty is not there when the server runs inside Eclipse
     * (its bundles are not in the feature), where no client sends any.
     */
    private DiagramServers diagrams;
    private volatile BiConsumer<String, Object> notifier = (method, params) -> {
    };

    @Override
    public CompletableFuture<InitializeResult> initialize(InitializeParams params) {
        StartupLog.mark("initialize received");
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
        // Only usable folders are indexed (a relative or odd root such as Neovim's "file://." made Xtext
        // scan "/"), all passed as workspace folders: Xtext reads them only if the client announced
        // them, so folders sent unannounced are used, and no folders at all work too.
        params.setWorkspaceFolders(folders.initial(params));
        params.setRootUri(null);
        params.setRootPath(null);
        workspace.setWorkspaceFolders(true);
        fileChanges.initialize(workspace.getDidChangeWatchedFiles(), folders.folders());
        return super.initialize(params).thenApply(result -> {
            StartupLog.mark("initialize answered (workspace built)");
            return result;
        });
    }

    @Override
    public void initialized(InitializedParams params) {
        super.initialized(params);
        fileChanges.start(getLanguageClient(), folders.folders());
        if (!Boolean.getBoolean("miron.lsp.noRenameWarmUp")) {
            RenameWarmUp.start(this);
        }
    }

    /** The workspace, for {@link RenameWarmUp}. */
    org.eclipse.xtext.ide.server.WorkspaceManager workspace() {
        return getWorkspaceManager();
    }

    @Override
    public CompletableFuture<Object> shutdown() {
        fileChanges.close();
        return super.shutdown();
    }

    // A document outside every folder (no workspace, or a refused root) brings its own folder in, so
    // the files it imports are found; the folder is added before the document is opened (writes
    // run in order).
    @Override
    public void didOpen(DidOpenTextDocumentParams params) {
        folders.cover(params.getTextDocument().getUri()).ifPresent(this::changeFolders);
        super.didOpen(params);
    }

    @Override
    public void didChangeWorkspaceFolders(DidChangeWorkspaceFoldersParams params) {
        changeFolders(folders.filter(params));
    }

    private void changeFolders(DidChangeWorkspaceFoldersParams change) {
        super.didChangeWorkspaceFolders(change);
        change.getEvent().getAdded().forEach(folder -> WorkspaceRoots.folder(folder.getUri()).ifPresent(fileChanges::watch));
    }

    // Diagrams (the sprotty-vscode protocol, org.miron.lsp.diagram): made again after every change,
    // in a read queued after the change's build.

    @JsonNotification("diagram/accept")
    public void diagramAccept(JsonObject message) {
        diagrams().accept(message);
    }

    @JsonNotification("diagram/didClose")
    public void diagramDidClose(String clientId) {
        diagrams().didClose(clientId);
    }

    /** Where the diagram servers send their notifications: the connection's JSON-RPC endpoint. */
    public void connectDiagrams(BiConsumer<String, Object> notifications) {
        this.notifier = notifications;
    }

    public synchronized DiagramServers diagrams() {
        if (diagrams == null) {
            diagrams = new DiagramServers((uri, expanded) -> getRequestManager().runRead(cancel -> getWorkspaceManager()
                    .doRead(uris.toUri(uri), (document, resource) -> DiagramGeneration.of(resource, expanded))),
                    uri -> uris.toUriString(org.eclipse.emf.common.util.URI.createURI(uri)));
            diagrams.connect(notifier);
        }
        return diagrams;
    }

    @Override
    protected void runBuildable(Supplier<? extends BuildManager.Buildable> newBuildable) {
        super.runBuildable(newBuildable);
        DiagramServers open;
        synchronized (this) {
            open = diagrams;
        }
        if (open != null) {
            open.refreshAll();
        }
    }

    // A position outside the document (a client racing an edit, or a buggy one) gets an empty
    // answer: Xtext would fail the request and log the whole document text.

    @Override
    protected Either<List<CompletionItem>, CompletionList> completion(CancelIndicator cancelIndicator,
            CompletionParams params) {
        try {
            return super.completion(cancelIndicator, params);
        } catch (IndexOutOfBoundsException outside) {
            return Either.forRight(new CompletionList());
        }
    }

    @Override
    protected Hover hover(HoverParams params, CancelIndicator cancelIndicator) {
        try {
            return super.hover(params, cancelIndicator);
        } catch (IndexOutOfBoundsException outside) {
            return IHoverService.EMPTY_HOVER;
        }
    }

    @Override
    protected List<? extends Location> definition(CancelIndicator cancelIndicator, DefinitionParams params) {
        try {
            return super.definition(cancelIndicator, params);
        } catch (IndexOutOfBoundsException outside) {
            return List.of();
        }
    }

    @Override
    protected List<? extends Location> references(ReferenceParams params, CancelIndicator cancelIndicator) {
        try {
            return super.references(params, cancelIndicator);
        } catch (IndexOutOfBoundsException outside) {
            return List.of();
        }
    }

    @Override
    protected List<? extends DocumentHighlight> documentHighlight(DocumentHighlightParams params,
            CancelIndicator cancelIndicator) {
        try {
            return super.documentHighlight(params, cancelIndicator);
        } catch (IndexOutOfBoundsException outside) {
            return List.of();
        }
    }

    @Inject
    private UriExtensions uris;

    // Issue 23, item 12: no edit that writes what is already there.
    @Override
    protected WorkspaceEdit rename(RenameParams params, CancelIndicator cancelIndicator) {
        return NoOpEdits.drop(super.rename(params, cancelIndicator),
                uri -> getWorkspaceManager().doRead(uris.toUri(uri), (document, resource) -> document));
    }

    /**
     * The server's own JSON-RPC methods. Xtext adds those of each language's ILanguageServerExtension,
     * which none of the three binds; asking the languages for them here would make LSP4J's launcher,
     * which wants the methods before it starts listening, wait for their set-up (MironLanguages
     * sets them up on their own thread while the server starts: docs/lsp.md, Start-up).
     */
    @Override
    public Map<String, JsonRpcMethod> supportedMethods() {
        return ServiceEndpoints.getSupportedMethods(getClass());
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
