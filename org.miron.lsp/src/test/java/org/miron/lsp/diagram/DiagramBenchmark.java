package org.miron.lsp.diagram;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;

import org.miron.testkit.Examples;
import org.miron.testkit.Folders;

import com.google.gson.JsonObject;

/**
 * `gradle :org.miron.lsp:diagramBenchmark`: keystroke to diagram update through the language
 * server, as the VS Code diagram sees it: a change sent (didChange), then the UpdateModelAction
 * received on diagram/accept (build, read, shapes, ELK layout, JSON). Printed, not asserted;
 * numbers in docs/diagrams.md (the target is 300 ms).
 */
public final class DiagramBenchmark {
    private static final int WARM_UP = 20;
    private static final int RUNS = 50;

    private DiagramBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        System.out.println("Keystroke -> diagram update through the language server (" + RUNS + " runs after " + WARM_UP
                + " warm-up runs; ms)");
        System.out.printf(Locale.ROOT, "%-44s %6s %8s %8s %8s%n", "file", "nodes", "median", "p90", "max");
        benchmark("intralogistics", "intralogistics.bt", "name=\"pick_retry\"");
        benchmark("intralogistics", "intralogistics.miron", null);
        benchmark("hospital-delivery", "hospital.bt", "name=\"handover\"");
        benchmark("hospital-delivery", "hospital.miron", null);
        System.exit(0);
    }

    /** {@code renamed} null: the keystroke is a space at the end (the diagram is made again all the same). */
    private static void benchmark(String example, String file, String renamed) throws Exception {
        Path workspace = Examples.copy(example);
        try (DiagramClient client = new DiagramClient()) {
            client.initialize(workspace);
            Path path = workspace.resolve(file);
            String text = Files.readString(path);
            String uri = client.open(path, text);
            JsonObject request = new JsonObject();
            request.addProperty("kind", "requestModel");
            JsonObject options = new JsonObject();
            options.addProperty("sourceUri", uri);
            request.add("options", options);
            request.addProperty("requestId", "bench");
            int mark = client.mark();
            client.send("bench", request);
            JsonObject graph = client.await(mark, r -> "setModel".equals(r.kind()), "setModel").action()
                    .getAsJsonObject("newRoot");
            int nodes = DiagramServerLspTest.treeNodes(graph).size();
            List<Double> times = new ArrayList<>();
            for (int i = 0; i < WARM_UP + RUNS; i++) {
                String edited = renamed == null ? text + " ".repeat(i % 2 + 1)
                        : text.replace(renamed, renamed.replace("=\"", "=\"x" + i));
                String expected = renamed == null ? null : "x" + i + renamed.substring(renamed.indexOf('"') + 1, renamed.length() - 1);
                int before = client.mark();
                long start = System.nanoTime();
                client.change(uri, edited);
                client.await(before, r -> "updateModel".equals(r.kind()) && (expected == null
                        || DiagramServerLspTest.titles(DiagramServerLspTest.treeNodes(r.action().getAsJsonObject("newRoot")))
                                .contains(expected)), "the update");
                if (i >= WARM_UP) {
                    times.add((System.nanoTime() - start) / 1e6);
                }
            }
            Collections.sort(times);
            System.out.printf(Locale.ROOT, "%-44s %6d %8.1f %8.1f %8.1f%n", example + "/" + file, nodes,
                    times.get(times.size() / 2), times.get((int) Math.ceil(times.size() * 0.9) - 1), times.get(times.size() - 1));
        } finally {
            Folders.delete(workspace);
        }
    }
}
