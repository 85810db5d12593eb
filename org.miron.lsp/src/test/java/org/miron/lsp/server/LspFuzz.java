package org.miron.lsp.server;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * `gradle :org.miron.lsp:lspFuzz -Pedits=N -Pseed=S`: the fuzz test's random typing for longer,
 * printing per request kind the count, the error answers and the latency percentiles; exits 1 on
 * any internal error or a dead server. Numbers go to docs/lsp.md.
 */
public final class LspFuzz {
    private LspFuzz() {
    }

    public static void main(String[] args) throws Exception {
        int edits = Integer.parseInt(System.getProperty("miron.fuzz.edits", "2000"));
        long seed = Long.parseLong(System.getProperty("miron.fuzz.seed", "1"));
        int every = Integer.parseInt(System.getProperty("miron.fuzz.every", "10"));
        boolean ok;
        try (LspFuzzer fuzzer = new LspFuzzer(seed)) {
            long start = System.nanoTime();
            fuzzer.run(edits, every);
            boolean alive = fuzzer.alive();
            System.out.printf(Locale.ROOT, "MIRoN language server fuzz: seed %d, %d edits, every request kind every %d edits, %.1f s%n",
                    seed, fuzzer.edits, every, (System.nanoTime() - start) / 1e9);
            System.out.printf(Locale.ROOT, "%-18s %6s %7s %8s %8s %8s %8s%n", "request", "count", "errors", "median", "p90", "p99", "max");
            int total = 0;
            for (Map.Entry<String, List<Double>> entry : fuzzer.latencies.entrySet()) {
                List<Double> sorted = new ArrayList<>(entry.getValue());
                Collections.sort(sorted);
                total += sorted.size();
                System.out.printf(Locale.ROOT, "%-18s %6d %7d %8.1f %8.1f %8.1f %8.1f%n", entry.getKey(), sorted.size(),
                        fuzzer.errorAnswers.getOrDefault(entry.getKey(), 0), percentile(sorted, 0.5),
                        percentile(sorted, 0.9), percentile(sorted, 0.99), sorted.get(sorted.size() - 1));
            }
            System.out.println(total + " requests (ms; errors: meaningful error answers), " + fuzzer.internalErrors.size()
                    + " internal errors, server " + (alive ? "alive" : "DEAD"));
            fuzzer.internalErrors.forEach(System.out::println);
            ok = alive && fuzzer.internalErrors.isEmpty();
        }
        System.exit(ok ? 0 : 1);
    }

    private static double percentile(List<Double> sorted, double p) {
        return sorted.get(Math.min(sorted.size() - 1, Math.max(0, (int) Math.ceil(sorted.size() * p) - 1)));
    }
}
