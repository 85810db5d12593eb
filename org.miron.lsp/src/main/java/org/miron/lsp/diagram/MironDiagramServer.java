package org.miron.lsp.diagram;

import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Consumer;

import org.eclipse.sprotty.Action;
import org.eclipse.sprotty.DefaultDiagramServer;
import org.eclipse.sprotty.FitToScreenAction;
import org.eclipse.sprotty.RequestModelAction;
import org.eclipse.sprotty.SEdge;
import org.eclipse.sprotty.SGraph;
import org.eclipse.sprotty.SModelElement;
import org.eclipse.sprotty.SModelRoot;
import org.eclipse.sprotty.ServerStatus;
import org.miron.diagram.SourceSpan;

/**
 * The server of one diagram client (one webview): Sprotty's default server, which keeps the
 * model, its revision, the selection and the expanded SubTree calls, with the model laid out
 * here (ELK, by org.miron.diagram) rather than by the client.
 */
public class MironDiagramServer extends DefaultDiagramServer {
    private final Consumer<MironDiagramServer> refresh;
    private volatile Map<String, SourceSpan> spans = Map.of();
    private volatile boolean shown;
    /** Whether the client has fitted a drawn model of this request's file to its view. */
    private volatile boolean fitted;
    /** The model request to answer (a SetModelAction with its request id: sprotty-vscode awaits it). */
    private volatile RequestModelAction request;
    private volatile ServerStatus lastStatus = ServerStatus.OK;
    private final AtomicLong requests = new AtomicLong();
    /** Space around the fitted diagram, in screen pixels. */
    private static final double FIT_PADDING = 20;

    /** @param refresh asks for this server's model again (the file, or its expanded calls, changed) */
    MironDiagramServer(String clientId, Consumer<MironDiagramServer> refresh) {
        super(clientId);
        this.refresh = refresh;
    }

    /** The document the client shows (the {@code sourceUri} of its model request), or null. */
    public String sourceUri() {
        return getOptions() == null ? null : getOptions().get("sourceUri");
    }

    public Set<String> expandedCalls() {
        return Set.copyOf(getDiagramState().getExpandedElements());
    }

    /** Where a node is written, or null. */
    public SourceSpan span(String elementId) {
        return spans.get(elementId);
    }

    // A model request (a new webview, or the panel now following another editor) is answered
    // once the file is read: the source may have changed, so the model is made again.
    // Requests, and the models that answer them, are taken under this server's lock: models are
    // read on several threads, and a read that ends late must never show an older file after a
    // newer one (Sprotty's server also drops, silently, a model whose revision was overtaken).
    @Override
    protected synchronized void handle(RequestModelAction request) {
        copyOptions(request);
        this.request = request;
        shown = false;
        fitted = false;
        spans = Map.of();
        refresh.accept(this);
    }

    /** A model to read: the file shown, the expanded calls, and the number that makes it the latest. */
    record Read(String uri, Set<String> expandedCalls, long number) {
    }

    /** The next model to read, which makes any earlier read stale; null when no file is shown yet. */
    synchronized Read nextRead() {
        String uri = sourceUri();
        return uri == null ? null : new Read(uri, expandedCalls(), requests.incrementAndGet());
    }

    boolean isLatest(long read) {
        return requests.get() == read;
    }

    /** Shows the model of a read, unless a newer read was asked for since. */
    synchronized void show(long read, DiagramGeneration.Generated generated, String file) {
        if (isLatest(read)) {
            show(generated, file);
        }
    }

    /** Says why the latest read has no model; the diagram keeps the last one. */
    synchronized void fail(long read, String message) {
        if (isLatest(read)) {
            status(new ServerStatus(ServerStatus.Severity.ERROR, message));
        }
    }

    /** Shows a new model: the first as a SetModelAction, the next ones as updates. */
    private void show(DiagramGeneration.Generated generated, String file) {
        if (!generated.parsed()) {
            status(new ServerStatus(ServerStatus.Severity.ERROR,
                    file + " does not parse: the diagram shows the last version that did"));
            if (!shown) {
                SGraph empty = new SGraph();
                empty.setType("graph");
                empty.setId("graph");
                first(empty);
            }
            return;
        }
        spans = generated.spans();
        status(ServerStatus.OK);
        SModelRoot root = generated.root();
        if (shown) {
            updateModel(root);
        } else {
            first(root);
        }
        if (!fitted) {
            fitted = true;
            dispatch(fitToScreen(root));
        }
    }

    // The first drawn model of a file (a new webview, the panel following another editor, or the
    // first version that parses) fits the view; updates as the user types keep their zoom and
    // scroll. Sprotty's client holds actions after a SetModel until it knows its canvas size. The
    // fit names the tree frames: with no ids, Sprotty fits the selection if there is one.
    static FitToScreenAction fitToScreen(SModelRoot root) {
        FitToScreenAction fit = new FitToScreenAction();
        List<String> frames = root.getChildren() == null ? List.of()
                : root.getChildren().stream().filter(c -> !(c instanceof SEdge)).map(SModelElement::getId).toList();
        fit.setElementIds(frames);
        fit.setPadding(FIT_PADDING);
        fit.setMaxZoom(1.0);
        fit.setAnimate(false);
        return fit;
    }

    // Sprotty's server answers a model request it is given as the cause of an update with a
    // SetModelAction carrying the request's id.
    private void first(SModelRoot root) {
        shown = true;
        RequestModelAction answered = request;
        request = null;
        if (answered != null) {
            updateModel(root, answered);
        } else {
            setModel(root);
        }
    }

    private void status(ServerStatus status) {
        if (!Objects.equals(status, lastStatus)) {
            lastStatus = status;
            setStatus(status);
        }
    }

    @Override
    protected boolean needsClientLayout(SModelRoot root) {
        return false;
    }

    @Override
    protected boolean needsServerLayout(SModelRoot root, Action cause) {
        return false;
    }
}
