package org.miron.lsp.server;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.ReferenceContext;
import org.eclipse.lsp4j.ReferenceParams;
import org.eclipse.lsp4j.RenameParams;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.eclipse.xtext.ide.server.UriExtensions;
import org.eclipse.xtext.ide.server.WorkspaceManager;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.resource.IResourceDescription;

/**
 * The first rename of a server took ≈ 1.4 s (issue 23, item 12): the classes of Xtext's rename
 * (RenameService2, ChangeSerializer, the reference updaters), each language's serializer and
 * formatter, built on first use. A second after the client said `initialized` (start-up done), one
 * thread of low priority renames a declared name in one file of each language of the workspace, and asks for
 * its references, through the server's own request handling; the answers are dropped (a rename only
 * computes edits, it changes nothing). A user request meanwhile runs beside it, an edit cancels it.
 */
final class RenameWarmUp {
    /** The language of each file extension the server knows. */
    private static final java.util.Map<String, String> LANGUAGES = java.util.Map.of("bt", "bt", "xml", "bt", "roqme",
            "roqme", "miron", "miron");
    private static final List<String> ORDER = List.of("bt", "roqme", "miron");

    private static final long DELAY_MS = 1000;

    private final MironLanguageServerImpl server;
    private final UriExtensions uris = new UriExtensions();

    private RenameWarmUp(MironLanguageServerImpl server) {
        this.server = server;
    }

    static void start(MironLanguageServerImpl server) {
        Thread thread = new Thread(new RenameWarmUp(server)::run, "miron-lsp-rename-warm-up");
        thread.setDaemon(true);
        thread.setPriority(Thread.MIN_PRIORITY);
        thread.start();
    }

    private void run() {
        try {
            // The client opens its files right after `initialized`: an edit or open cancels a
            // running read, so the warm-up waits for that first burst.
            Thread.sleep(DELAY_MS);
            List<TextDocumentPosition> targets = server.getRequestManager()
                    .runRead(cancel -> targets(server.workspace())).get(5, TimeUnit.MINUTES);
            for (TextDocumentPosition target : targets) {
                TextDocumentIdentifier document = new TextDocumentIdentifier(target.uri());
                server.rename(new RenameParams(document, target.position(), "miron_warm_up")).handle((r, e) -> null)
                        .get(5, TimeUnit.MINUTES);
                server.references(new ReferenceParams(document, target.position(), new ReferenceContext(true)))
                        .handle((r, e) -> null).get(5, TimeUnit.MINUTES);
                StartupLog.mark("rename warmed up in a ." + target.extension());
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (Exception | LinkageError e) {
            // only the saving is lost: the first rename does it then
        }
    }

    /** A place to rename at (a class, not a record: Gradle 4.4 warns about records on the compile class path). */
    private static final class TextDocumentPosition {
        private final String uri;
        private final Position position;

        TextDocumentPosition(String uri, Position position) {
            this.uri = uri;
            this.position = position;
        }

        String uri() {
            return uri;
        }

        Position position() {
            return position;
        }

        String extension() {
            return uri.substring(uri.lastIndexOf('.') + 1);
        }
    }

    /** A declared name in one file of each language (by extension), as the index lists them. */
    private List<TextDocumentPosition> targets(WorkspaceManager workspace) {
        List<TextDocumentPosition> targets = new ArrayList<>();
        Set<String> done = new HashSet<>();
        for (IResourceDescription resource : workspace.getIndex().getAllResourceDescriptions()) {
            URI uri = resource.getURI();
            String language = LANGUAGES.get(uri.fileExtension());
            if (language == null || done.contains(language)) {
                continue;
            }
            for (IEObjectDescription exported : resource.getExportedObjects()) {
                Position position = workspace.doRead(uri, (document, xtext) -> {
                    EObject element = xtext.getEObject(exported.getEObjectURI().fragment());
                    INode name = element == null ? null : nameNode(element);
                    return name == null ? null : document.getPosition(name.getOffset() + 1);
                });
                if (position != null) {
                    targets.add(new TextDocumentPosition(uris.toUriString(uri), position));
                    done.add(language);
                    break;
                }
            }
        }
        // A tree's rename also rewrites the .miron using it, a property's too: those two warm up the most.
        targets.sort(java.util.Comparator.comparing(t -> ORDER.indexOf(LANGUAGES.get(t.extension()))));
        return targets;
    }

    private static INode nameNode(EObject element) {
        EStructuralFeature name = element.eClass().getEStructuralFeature("name");
        if (name == null) {
            return null;
        }
        List<INode> nodes = NodeModelUtils.findNodesForFeature(element, name);
        return nodes.isEmpty() ? null : nodes.get(0);
    }
}
