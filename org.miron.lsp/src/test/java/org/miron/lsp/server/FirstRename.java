package org.miron.lsp.server;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import org.eclipse.lsp4j.ReferenceContext;
import org.eclipse.lsp4j.ReferenceParams;
import org.eclipse.lsp4j.RenameParams;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.miron.testkit.Examples;
import org.miron.testkit.Folders;
import org.miron.testkit.lsp.LspClient;

/**
 * `gradle :org.miron.lsp:lspFirstRename [-Pstarts=N] [-Pidle=MS]`: how long an editor user waits
 * for the first rename and the first find-references in a fresh server process (issue 23, item
 * 12). Each run spawns the server on its class path, opens intralogistics.miron, waits for its
 * diagnostics and then idles as a user reading the file does (-Pidle, default 3000 ms) before
 * renaming the tree Charge from the .miron; a second rename and the references follow. Printed,
 * not asserted (docs/lsp.md, First rename). Servers with and without the rename warm-up
 * ({@code RenameWarmUp}) alternate.
 */
public final class FirstRename {
    private FirstRename() {
    }

    public static void main(String[] args) throws Exception {
        int starts = Integer.parseInt(System.getProperty("miron.benchmark.starts", "5"));
        long idle = Long.parseLong(System.getProperty("miron.benchmark.idle", "3000"));
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        String classpath = System.getProperty("miron.lsp.classpath");
        Map<String, List<String>> variants = new LinkedHashMap<>();
        String timing = "-Dmiron.lsp.timing=" + Boolean.getBoolean("miron.benchmark.timing");
        variants.put("with the rename warm-up (default)",
                List.of(java, "-Xss4m", timing, "-cp", classpath, MironLanguageServer.class.getName()));
        variants.put("without (-Dmiron.lsp.noRenameWarmUp=true)", List.of(java, "-Xss4m", timing,
                "-Dmiron.lsp.noRenameWarmUp=true", "-cp", classpath, MironLanguageServer.class.getName()));
        once(variants.values().iterator().next(), idle); // untimed: the client's own warm-up
        // The variants alternate, so that the machine's load weighs on both alike.
        Map<String, List<double[]>> runs = new LinkedHashMap<>();
        for (int i = 0; i < starts; i++) {
            for (Map.Entry<String, List<String>> variant : variants.entrySet()) {
                runs.computeIfAbsent(variant.getKey(), k -> new ArrayList<>()).add(once(variant.getValue(), idle));
            }
        }
        System.out.printf(Locale.ROOT, "%d fresh server processes each, %d ms idle after the first diagnostics; ms: min / median / worst%n",
                starts, idle);
        for (Map.Entry<String, List<double[]>> variant : runs.entrySet()) {
            System.out.println(variant.getKey());
            Spread.print("  spawn -> first diagnostics", 46, variant.getValue(), 3);
            Spread.print("  first rename (tree Charge, from the .miron)", 46, variant.getValue(), 0);
            Spread.print("  second rename", 46, variant.getValue(), 1);
            Spread.print("  first references", 46, variant.getValue(), 2);
        }
        System.exit(0);
    }

    private static double[] once(List<String> command, long idle) throws Exception {
        Path workspace = Examples.copy("intralogistics");
        long spawn = System.nanoTime();
        Process process = new ProcessBuilder(command)
                .redirectError(ProcessBuilder.Redirect.appendTo(workspace.resolve("server.log").toFile())).start();
        try {
            LspClient client = new LspClient(process.getInputStream(), process.getOutputStream());
            client.initialize(workspace);
            Path miron = workspace.resolve("intralogistics.miron");
            String text = Files.readString(miron);
            String uri = client.open(miron, text);
            client.awaitDiagnostics(uri, d -> true);
            double diagnosed = (System.nanoTime() - spawn) / 1e6;
            Thread.sleep(idle);
            TextDocumentIdentifier document = new TextDocumentIdentifier(uri);
            long start = System.nanoTime();
            client.server().getTextDocumentService().rename(new RenameParams(document,
                    IntralogisticsLspTest.positionAfter(text, "dock : main.Cha"), "Dock")).get(60, TimeUnit.SECONDS);
            double first = (System.nanoTime() - start) / 1e6;
            start = System.nanoTime();
            client.server().getTextDocumentService().rename(new RenameParams(document,
                    IntralogisticsLspTest.positionAfter(text, "dock : main.Cha"), "Docking")).get(60, TimeUnit.SECONDS);
            double second = (System.nanoTime() - start) / 1e6;
            start = System.nanoTime();
            client.server().getTextDocumentService().references(new ReferenceParams(document,
                    IntralogisticsLspTest.positionAfter(text, "dock : main.Cha"), new ReferenceContext(true)))
                    .get(60, TimeUnit.SECONDS);
            double references = (System.nanoTime() - start) / 1e6;
            client.server().shutdown().get(60, TimeUnit.SECONDS);
            client.server().exit();
            process.waitFor(60, TimeUnit.SECONDS);
            if (Boolean.getBoolean("miron.benchmark.timing")) {
                // -Ptiming: the server's start-up log (StartupLog), to see when the warm-up ended.
                Files.readAllLines(workspace.resolve("server.log")).stream().filter(l -> l.startsWith("miron lsp:"))
                        .forEach(l -> System.out.println("  " + l));
            }
            return new double[] { first, second, references, diagnosed };
        } finally {
            process.destroyForcibly();
            Folders.delete(workspace);
        }
    }
}
