package org.miron.lsp.server;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.stream.Stream;

import org.eclipse.lsp4j.CodeActionContext;
import org.eclipse.lsp4j.CodeActionParams;
import org.eclipse.lsp4j.CompletionParams;
import org.eclipse.lsp4j.DefinitionParams;
import org.eclipse.lsp4j.Diagnostic;
import org.eclipse.lsp4j.DocumentFormattingParams;
import org.eclipse.lsp4j.DocumentHighlightParams;
import org.eclipse.lsp4j.DocumentRangeFormattingParams;
import org.eclipse.lsp4j.DocumentSymbolParams;
import org.eclipse.lsp4j.ExecuteCommandParams;
import org.eclipse.lsp4j.FoldingRangeRequestParams;
import org.eclipse.lsp4j.FormattingOptions;
import org.eclipse.lsp4j.HoverParams;
import org.eclipse.lsp4j.InitializeResult;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.PrepareRenameParams;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.ReferenceContext;
import org.eclipse.lsp4j.ReferenceParams;
import org.eclipse.lsp4j.RenameParams;
import org.eclipse.lsp4j.SemanticTokensParams;
import org.eclipse.lsp4j.ServerCapabilities;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.eclipse.lsp4j.jsonrpc.ResponseErrorException;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseError;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseErrorCode;
import org.eclipse.lsp4j.services.TextDocumentService;
import org.miron.testkit.Folders;
import org.miron.testkit.RepositoryRoot;
import org.miron.testkit.lsp.LspClient;

/**
 * Types like a careless user: random edits (deleted spans, brackets, quotes, keywords, tabs,
 * non-ASCII) on copies of the examples and of BehaviorTree.CPP 4 trees, and every few edits asks
 * every request kind the server offers through the real LSP client. Records each request's latency
 * and every internal error (an LSP InternalError, or any error whose data holds a stack trace).
 * Seeded: the same seed makes the same edits. Used by {@link LspFuzzTest} and the `lspFuzz` task.
 */
public final class LspFuzzer implements AutoCloseable {
    private static final long TIMEOUT_SECONDS = 30;
    private static final String[] INSERTS = { "<", ">", "/>", "</", "{", "}", "(", ")", "[", "]", "\"", "'", "\"\"",
            "=", ":", "::", ".", ",", ";", "\t", "\n", " ", "é", "中", "😀", "\u00a0", "ß", "import ", "roqme ",
            "miron ", "context ", "property ", "observation ", "affects ", "reinforces ", "undermines ", "@varpoint ",
            "rule ", "implies ", "preset ", "when ", "<Sequence>", "</Sequence>", "<SubTree ID=\"", "ID=\"",
            "<BehaviorTree ID=\"X\">", "<TreeNodesModel>", "<Action ", "BTCPP_format=\"4\"", "{x}", "/**", "*/",
            "<!--", "-->", "++", "---", "0.5", "-1", "enum ", "number ", "boolean " };

    private final Random random;
    private final Path workspace;
    private final LspClient client;
    private final ServerCapabilities capabilities;
    private final Map<String, String> texts = new LinkedHashMap<>();
    private final Map<String, String> originals = new LinkedHashMap<>();
    private final Map<String, Path> paths = new LinkedHashMap<>();
    /** Latencies in ms per request kind. */
    public final Map<String, List<Double>> latencies = new LinkedHashMap<>();
    /** Internal errors, one line each: request kind, file, message. */
    public final List<String> internalErrors = new ArrayList<>();
    /** Meaningful error answers per request kind (not internal errors). */
    public final Map<String, Integer> errorAnswers = new LinkedHashMap<>();
    public int edits;
    /** Where the last edit was: half the requests ask there, as an editor asks at the cursor. */
    private int cursor;

    public LspFuzzer(long seed) throws Exception {
        random = new Random(seed);
        workspace = Files.createTempDirectory("miron-lsp-fuzz");
        Path root = RepositoryRoot.path();
        copy(root.resolve("examples/intralogistics"), workspace.resolve("intralogistics"));
        copy(root.resolve("examples/hospital-delivery"), workspace.resolve("hospital-delivery"));
        Path v4 = root.resolve("org.miron.bt/src/test/resources/bt/valid");
        try (Stream<Path> files = Files.list(v4)) {
            for (Path file : (Iterable<Path>) files.filter(f -> f.getFileName().toString().startsWith("v4_"))::iterator) {
                copy(file.getParent(), workspace.resolve("v4"), file.getFileName().toString());
            }
        }
        client = new LspClient();
        InitializeResult result = client.initialize(workspace);
        capabilities = result.getCapabilities();
        try (Stream<Path> files = Files.walk(workspace)) {
            for (Path file : (Iterable<Path>) files.filter(Files::isRegularFile).sorted()::iterator) {
                String text = Files.readString(file);
                String uri = client.open(file, text);
                texts.put(uri, text);
                originals.put(uri, text);
                paths.put(uri, file);
            }
        }
        for (String uri : texts.keySet()) {
            client.awaitDiagnostics(uri, d -> true);
        }
    }

    private static void copy(Path from, Path to) throws IOException {
        try (Stream<Path> files = Files.list(from)) {
            for (Path file : (Iterable<Path>) files.filter(f -> f.toString().matches(".*\\.(bt|roqme|miron)"))::iterator) {
                copy(from, to, file.getFileName().toString());
            }
        }
    }

    private static void copy(Path from, Path to, String name) throws IOException {
        Files.createDirectories(to);
        Files.copy(from.resolve(name), to.resolve(name));
    }

    /** Makes {@code count} random edits, asking every request kind after each {@code every} edits. */
    public void run(int count, int every) throws Exception {
        List<String> uris = new ArrayList<>(texts.keySet());
        for (int i = 1; i <= count; i++) {
            String uri = uris.get(random.nextInt(uris.size()));
            // Now and then the user starts again from a valid file, so edits do not only pile up.
            String text = random.nextInt(25) == 0 ? originals.get(uri) : edit(texts.get(uri));
            cursor = Math.min(cursor, text.length());
            texts.put(uri, text);
            client.change(uri, text);
            edits++;
            if (i % every == 0) {
                askEverything(uri);
            }
        }
    }

    private String edit(String text) {
        int at = text.isEmpty() ? 0 : random.nextInt(text.length() + 1);
        cursor = at;
        // Never split a surrogate pair: a client's buffer holds whole characters.
        if (at > 0 && at < text.length() && Character.isLowSurrogate(text.charAt(at))) {
            at--;
        }
        if (random.nextInt(3) == 0 && at < text.length()) {
            int end = Math.min(text.length(), at + 1 + random.nextInt(40));
            if (end < text.length() && Character.isLowSurrogate(text.charAt(end))) {
                end++;
            }
            return text.substring(0, at) + text.substring(end);
        }
        return text.substring(0, at) + INSERTS[random.nextInt(INSERTS.length)] + text.substring(at);
    }

    private int nearCursor(String text) {
        int at = Math.max(0, Math.min(text.length(), cursor + random.nextInt(7) - 3));
        return at > 0 && at < text.length() && Character.isLowSurrogate(text.charAt(at)) ? at - 1 : at;
    }

    private Position randomPosition(String text) {
        int at = text.isEmpty() ? 0 : random.nextInt(text.length() + 1);
        if (at > 0 && at < text.length() && Character.isLowSurrogate(text.charAt(at))) {
            at--;
        }
        return TextEdits.position(text, at);
    }

    /** Every request kind on the file just edited, at random positions. */
    private void askEverything(String uri) throws Exception {
        String text = texts.get(uri);
        TextDocumentIdentifier doc = new TextDocumentIdentifier(uri);
        TextDocumentService service = client.server().getTextDocumentService();
        Position at = randomPosition(text);
        Position to = randomPosition(text);
        if (to.getLine() < at.getLine() || to.getLine() == at.getLine() && to.getCharacter() < at.getCharacter()) {
            Position swap = at;
            at = to;
            to = swap;
        }
        Range range = new Range(at, to);
        Position point = random.nextBoolean() ? at : TextEdits.position(text, nearCursor(text));
        ask("completion", uri, () -> service.completion(new CompletionParams(doc, point)));
        ask("hover", uri, () -> service.hover(new HoverParams(doc, point)));
        ask("definition", uri, () -> service.definition(new DefinitionParams(doc, point)));
        ask("references", uri, () -> service.references(new ReferenceParams(doc, point, new ReferenceContext(true))));
        ask("documentHighlight", uri, () -> service.documentHighlight(new DocumentHighlightParams(doc, point)));
        ask("documentSymbol", uri, () -> service.documentSymbol(new DocumentSymbolParams(doc)));
        ask("formatting", uri, () -> service.formatting(new DocumentFormattingParams(doc, new FormattingOptions(4, true))));
        ask("rangeFormatting", uri, () -> service.rangeFormatting(
                new DocumentRangeFormattingParams(doc, new FormattingOptions(4, true), range)));
        List<Diagnostic> diagnostics = client.published(uri);
        List<Diagnostic> context = diagnostics == null ? List.of() : new ArrayList<>(diagnostics);
        ask("codeAction", uri, () -> service.codeAction(new CodeActionParams(doc, range, new CodeActionContext(context))));
        ask("prepareRename", uri, () -> service.prepareRename(new PrepareRenameParams(doc, point)));
        ask("rename", uri, () -> service.rename(new RenameParams(doc, point, "renamed")));
        ask("foldingRange", uri, () -> service.foldingRange(new FoldingRangeRequestParams(doc)));
        if (capabilities.getSemanticTokensProvider() != null) {
            ask("semanticTokens", uri, () -> service.semanticTokensFull(new SemanticTokensParams(doc)));
        }
        // Both commands on every kind of file: the wrong kind must be a meaningful error too.
        String version = random.nextBoolean() ? "3" : "4";
        ask("miron.generate", uri, () -> client.server().getWorkspaceService()
                .executeCommand(new ExecuteCommandParams("miron.generate", List.of(uri))));
        ask("miron.convert", uri, () -> client.server().getWorkspaceService()
                .executeCommand(new ExecuteCommandParams("miron.convert", List.of(uri, version))));
    }

    private interface Request {
        CompletableFuture<?> send();
    }

    private void ask(String kind, String uri, Request request) throws Exception {
        long start = System.nanoTime();
        try {
            request.send().get(TIMEOUT_SECONDS, TimeUnit.SECONDS);
        } catch (ExecutionException e) {
            if (!(e.getCause() instanceof ResponseErrorException)) {
                throw e;
            }
            ResponseError error = ((ResponseErrorException) e.getCause()).getResponseError();
            String data = String.valueOf(error.getData());
            if (error.getCode() == ResponseErrorCode.InternalError.getValue() || data.contains("\tat ")
                    || data.contains("Exception") || error.getMessage().startsWith(GuardedRequestManager.MESSAGE)) {
                internalErrors.add(kind + " " + workspace.relativize(paths.get(uri)) + ": " + error.getMessage()
                        + " " + firstLines(data));
            } else {
                errorAnswers.merge(kind, 1, Integer::sum);
            }
        } catch (TimeoutException e) {
            throw new AssertionError(kind + " on " + uri + ": no answer within " + TIMEOUT_SECONDS + " s (server dead?)");
        }
        latencies.computeIfAbsent(kind, k -> new ArrayList<>()).add((System.nanoTime() - start) / 1e6);
    }

    private static String firstLines(String data) {
        String[] lines = data.split("\n");
        StringBuilder result = new StringBuilder();
        for (int i = 0; i < Math.min(4, lines.length); i++) {
            result.append(lines[i].trim()).append(" | ");
        }
        return result.toString();
    }

    /** Whether the server still answers: a fresh file gets diagnostics and its outline. */
    public boolean alive() throws Exception {
        Path probe = workspace.resolve("probe-" + edits + ".roqme");
        String uri = client.open(probe, "roqme Probe\ncontext C : boolean\n");
        client.awaitDiagnostics(uri, d -> true);
        return client.server().getTextDocumentService().documentSymbol(new DocumentSymbolParams(new TextDocumentIdentifier(uri)))
                .get(TIMEOUT_SECONDS, TimeUnit.SECONDS) != null;
    }

    @Override
    public void close() throws Exception {
        try {
            client.close();
        } finally {
            Folders.delete(workspace);
        }
    }
}
