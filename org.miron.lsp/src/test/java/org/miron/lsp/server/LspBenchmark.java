package org.miron.lsp.server;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;

import org.eclipse.lsp4j.CompletionParams;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.miron.testkit.Examples;
import org.miron.testkit.Folders;
import org.miron.testkit.lsp.LspClient;

/**
 * `gradle :org.miron.lsp:lspBenchmark`: latencies of the language server seen by an LSP client
 * (JSON-RPC over piped streams, as in the tests), printed, not asserted. Numbers go to docs/lsp.md.
 * The start-up of a server process is lspStartup's ({@link ServerStartup}).
 */
public final class LspBenchmark {
    private static final int WARM_UP = 10;
    private static final int RUNS = 50;

    private LspBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        System.out.println("MIRoN language server latencies (" + RUNS + " runs after " + WARM_UP + " warm-up runs; ms)");
        System.out.printf(Locale.ROOT, "%-58s %8s %8s %8s%n", "measure", "median", "p90", "max");
        for (String example : List.of("intralogistics", "hospital-delivery")) {
            benchmark(example);
        }
        System.exit(0);
    }

    private static void benchmark(String example) throws Exception {
        Path workspace = Examples.copy(example);
        try {
            Path miron = Files.list(workspace).filter(p -> p.toString().endsWith(".miron")).findFirst().get();
            Path roqme = Files.list(workspace).filter(p -> p.toString().endsWith(".roqme")).findFirst().get();
            String text = Files.readString(miron);

            long start = System.nanoTime();
            LspClient client = new LspClient();
            client.initialize(workspace);
            String uri = client.open(miron, text);
            client.awaitDiagnostics(uri, d -> true);
            print(example + ": start, initialize, first diagnostics", List.of(ms(System.nanoTime() - start)));

            // A keystroke: one character typed into (then removed from) a name, so the diagnostics change.
            int at = text.indexOf("affects ") + "affects ".length();
            List<Double> keystroke = new ArrayList<>();
            for (int i = 0; i < WARM_UP + RUNS; i++) {
                String edited = i % 2 == 0 ? text.substring(0, at) + "x" + text.substring(at) : text;
                client.forget(uri);
                long t = System.nanoTime();
                client.change(uri, edited);
                client.awaitDiagnostics(uri, d -> true);
                if (i >= WARM_UP) {
                    keystroke.add(ms(System.nanoTime() - t));
                }
            }
            print(example + ": keystroke in .miron -> its diagnostics", keystroke);

            // A keystroke in the imported .roqme: the .miron's diagnostics follow.
            String roqmeText = Files.readString(roqme);
            String roqmeUri = client.open(roqme, roqmeText);
            client.awaitDiagnostics(roqmeUri, d -> true);
            int end = roqmeText.length();
            List<Double> imported = new ArrayList<>();
            for (int i = 0; i < WARM_UP + RUNS; i++) {
                String edited = i % 2 == 0 ? roqmeText.substring(0, end) + "\n" : roqmeText;
                client.forget(uri);
                long t = System.nanoTime();
                client.change(roqmeUri, edited);
                client.awaitDiagnostics(uri, d -> true);
                if (i >= WARM_UP) {
                    imported.add(ms(System.nanoTime() - t));
                }
            }
            print(example + ": keystroke in .roqme -> .miron diagnostics", imported);

            List<Double> completion = new ArrayList<>();
            CompletionParams params = new CompletionParams(new TextDocumentIdentifier(uri),
                    TextEdits.position(text, at));
            for (int i = 0; i < WARM_UP + RUNS; i++) {
                long t = System.nanoTime();
                client.server().getTextDocumentService().completion(params).get(60, TimeUnit.SECONDS);
                if (i >= WARM_UP) {
                    completion.add(ms(System.nanoTime() - t));
                }
            }
            print(example + ": completion after 'affects '", completion);
            client.close();
        } finally {
            Folders.delete(workspace);
        }
    }

    private static double ms(long nanos) {
        return nanos / 1e6;
    }

    private static void print(String measure, List<Double> values) {
        List<Double> sorted = new ArrayList<>(values);
        Collections.sort(sorted);
        double median = sorted.get(sorted.size() / 2);
        double p90 = sorted.get(Math.min(sorted.size() - 1, (int) Math.ceil(sorted.size() * 0.9) - 1));
        double max = sorted.get(sorted.size() - 1);
        System.out.printf(Locale.ROOT, "%-58s %8.1f %8.1f %8.1f%n", measure, median, p90, max);
    }
}
