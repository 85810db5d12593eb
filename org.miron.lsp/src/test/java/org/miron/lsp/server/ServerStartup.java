package org.miron.lsp.server;

import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import org.miron.testkit.Examples;
import org.miron.testkit.Folders;
import org.miron.testkit.lsp.LspClient;

/**
 * `gradle :org.miron.lsp:lspStartup`: the start-up an editor user waits for. A server process is
 * spawned as an editor spawns it, `./miron lsp` (AppCDS archive, unsigned jars, C1), and for
 * comparison plain java on the server's class path; the client times `initialize` answered and
 * the first diagnostics of the opened intralogistics.miron from the spawn, with the server's CPU
 * time until then. The variants alternate, so that the machine's load weighs on both alike; with
 * -Pbusy a second process keeps a core busy all along. Printed, not asserted (docs/lsp.md).
 */
public final class ServerStartup {
    private ServerStartup() {
    }

    public static void main(String[] args) throws Exception {
        int starts = Integer.parseInt(System.getProperty("miron.benchmark.starts", "10"));
        boolean busy = Boolean.getBoolean("miron.benchmark.busy");
        Path launcher = Path.of(System.getProperty("miron.root"), "miron");
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Map<String, List<String>> variants = new LinkedHashMap<>();
        variants.put("./miron lsp", List.of(launcher.toString(), "lsp"));
        String classpath = System.getProperty("miron.lsp.classpath");
        if (classpath != null && !Boolean.getBoolean("miron.benchmark.launcherOnly")) {
            variants.put("java -cp <server jars> (no archive, C2)",
                    List.of(java, "-Xss4m", "-cp", classpath, MironLanguageServer.class.getName()));
        }
        // Untimed: the first `./miron lsp` after a build trains its archive; the client warms up.
        long warmUp = System.nanoTime();
        once(variants.get("./miron lsp"));
        System.out.printf(Locale.ROOT, "warm-up start of ./miron lsp (trains the archive after a build): %.0f ms%n",
                (System.nanoTime() - warmUp) / 1e6);

        Process spinner = busy ? new ProcessBuilder("sh", "-c", "while :; do :; done").start() : null;
        try {
            Map<String, List<double[]>> times = new LinkedHashMap<>();
            for (int i = 0; i < starts; i++) {
                for (Map.Entry<String, List<String>> variant : variants.entrySet()) {
                    times.computeIfAbsent(variant.getKey(), k -> new ArrayList<>()).add(once(variant.getValue()));
                }
            }
            System.out.printf(Locale.ROOT, "%d fresh server processes each%s; ms: min / median / worst%n", starts,
                    busy ? ", with a second process keeping one core busy" : "");
            for (Map.Entry<String, List<double[]>> variant : times.entrySet()) {
                System.out.println(variant.getKey());
                Spread.print("  spawn -> initialize answered", 44, variant.getValue(), 0);
                Spread.print("  spawn -> first .miron diagnostics", 44, variant.getValue(), 1);
                // CPU time depends less on what else the machine runs than wall time does.
                Spread.print("  server CPU until then", 44, variant.getValue(), 2);
            }
        } finally {
            if (spinner != null) {
                spinner.destroyForcibly();
            }
        }
        System.out.printf(Locale.ROOT, "load average at the end: %.1f%n",
                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage());
        System.exit(0);
    }

    /** One editor session: spawn, initialize, open the model, its diagnostics; then shutdown and exit. */
    private static double[] once(List<String> command) throws Exception {
        Path workspace = Examples.copy("intralogistics");
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
}
