package org.miron.lsp.server;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import org.miron.testkit.Examples;
import org.miron.testkit.Folders;
import org.miron.testkit.lsp.LspClient;

/**
 * The start-up an editor user waits for, measured by lspBenchmark: a server process is spawned
 * (java on the server's jar class path, as `miron lsp` runs it), and the client times `initialize`
 * answered and the first diagnostics of the opened intralogistics.miron, from the spawn. Several
 * fresh processes each, without and with the AppCDS archive of `lspArchive`, and with the C1
 * compiler only (as `./miron lsp` runs); printed, not asserted, with the server's CPU time.
 */
final class ServerStartup {
    private ServerStartup() {
    }

    static void benchmark() throws Exception {
        String classpath = System.getProperty("miron.lsp.classpath");
        if (classpath == null) {
            System.out.println("(no miron.lsp.classpath: process start-up not measured)");
            return;
        }
        int starts = Integer.parseInt(System.getProperty("miron.benchmark.starts", "5"));
        String archive = System.getProperty("miron.lsp.archive", "");
        List<List<String>> variants = new ArrayList<>();
        variants.add(List.of());
        if (!archive.isEmpty() && new File(archive).isFile()) {
            variants.add(List.of("-XX:SharedArchiveFile=" + archive, "-Xlog:cds=off"));
            // What `./miron lsp` runs: the archive and the C1 compiler only.
            variants.add(List.of("-XX:SharedArchiveFile=" + archive, "-Xlog:cds=off", "-XX:TieredStopAtLevel=1"));
        }
        System.out.printf(Locale.ROOT, "%-58s %8s %8s %8s%n", "process start-up (" + starts + " fresh processes each)",
                "min", "median", "max");
        for (List<String> flags : variants) {
            List<Double> initialized = new ArrayList<>();
            List<Double> diagnosed = new ArrayList<>();
            List<Double> cpu = new ArrayList<>();
            for (int i = 0; i < starts; i++) {
                double[] times = once(classpath, flags);
                initialized.add(times[0]);
                diagnosed.add(times[1]);
                cpu.add(times[2]);
            }
            String name = flags.isEmpty() ? "no archive" : flags.size() == 2 ? "archive" : "archive, C1";
            print("spawn -> initialize answered (" + name + ")", initialized);
            print("spawn -> first .miron diagnostics (" + name + ")", diagnosed);
            // CPU time depends less on what else the machine runs than wall time does.
            print("  server CPU until then (" + name + ")", cpu);
        }
    }

    private static double[] once(String classpath, List<String> flags) throws Exception {
        Path workspace = Examples.copy("intralogistics");
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xss4m"));
        command.addAll(flags);
        command.addAll(List.of("-cp", classpath, MironLanguageServer.class.getName()));
        long start = System.nanoTime();
        Process process = new ProcessBuilder(command)
                .redirectError(ProcessBuilder.Redirect.appendTo(workspace.resolve("server.log").toFile())).start();
        try {
            LspClient client = new LspClient(process.getInputStream(), process.getOutputStream());
            client.initialize(workspace);
            double initialized = (System.nanoTime() - start) / 1e6;
            Path miron = workspace.resolve("intralogistics.miron");
            String uri = client.open(miron, Files.readString(miron));
            client.awaitDiagnostics(uri, d -> true);
            double diagnosed = (System.nanoTime() - start) / 1e6;
            double cpu = process.toHandle().info().totalCpuDuration().map(d -> d.toNanos() / 1e6).orElse(Double.NaN);
            client.server().shutdown().get(60, TimeUnit.SECONDS);
            client.server().exit();
            process.waitFor(60, TimeUnit.SECONDS);
            return new double[] { initialized, diagnosed, cpu };
        } finally {
            process.destroyForcibly();
            Folders.delete(workspace);
        }
    }

    private static void print(String measure, List<Double> values) {
        List<Double> sorted = new ArrayList<>(values);
        Collections.sort(sorted);
        System.out.printf(Locale.ROOT, "%-58s %8.0f %8.0f %8.0f%n", measure, sorted.get(0), sorted.get(sorted.size() / 2),
                sorted.get(sorted.size() - 1));
    }
}
