package org.miron.runtime.sim;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.miron.runtime.Json;

/**
 * Runs every policy N times on the same world, in parallel on a pool of threads, and gathers the
 * measures. Run i of every policy uses seed {@code seed + i}, so the policies meet the same random
 * situations as far as their own behaviour lets them (common random numbers); results are ordered
 * by policy and run, whatever thread ran them, so the same seed gives the same summary, byte for byte.
 */
public final class Comparison {
    /** One policy's runs, in run order; run 0 carries the timeline for the report. */
    public record PolicyRuns(Policy policy, List<Simulation.Result> runs) {
    }

    private Comparison() {
    }

    public static List<PolicyRuns> run(Setup setup, List<Policy> policies, int runs, long seed, long durationMs,
            long timelineMs, int threads) throws InterruptedException {
        ExecutorService pool = Executors.newFixedThreadPool(Math.max(1, threads), r -> {
            Thread t = new Thread(r, "simulate");
            t.setDaemon(true);
            return t;
        });
        try {
            List<List<Future<Simulation.Result>>> futures = new ArrayList<>();
            for (Policy p : policies) {
                List<Future<Simulation.Result>> fs = new ArrayList<>();
                for (int i = 0; i < runs; i++) {
                    long s = seed + i;
                    long timeline = i == 0 ? timelineMs : -1;
                    fs.add(pool.submit(() -> new Simulation(setup, p, s, durationMs, timeline).run()));
                }
                futures.add(fs);
            }
            List<PolicyRuns> out = new ArrayList<>();
            for (int i = 0; i < policies.size(); i++) {
                List<Simulation.Result> results = new ArrayList<>();
                for (Future<Simulation.Result> f : futures.get(i)) {
                    try {
                        results.add(f.get());
                    } catch (ExecutionException e) {
                        Throwable c = e.getCause();
                        throw c instanceof RuntimeException re ? re : new IllegalStateException(c);
                    }
                }
                out.add(new PolicyRuns(policies.get(i), results));
            }
            return out;
        } finally {
            pool.shutdownNow();
        }
    }

    /** Each policy's coverage, its runs merged. */
    public static List<CoverageTable.Column> coverage(List<PolicyRuns> results) {
        return CoverageTable.of(results);
    }

    /** The measures' names in order: the world's, then the metrics' means and the run counters. */
    public static List<String> measureNames(List<PolicyRuns> results) {
        Set<String> names = new LinkedHashSet<>();
        results.forEach(r -> r.runs().forEach(x -> names.addAll(x.measures().keySet())));
        return List.copyOf(names);
    }

    /** {@code {"policies": {"adaptive": {"<measure>": {"mean", "ci95": [lo, hi], "runs": [...]}}}}} plus the settings. */
    public static ObjectNode summary(List<PolicyRuns> results, int runs, long seed, long durationMs) {
        ObjectNode root = Json.object();
        root.put("durationS", durationMs / 1000.0);
        root.put("runs", runs);
        root.put("seed", seed);
        ObjectNode policies = root.putObject("policies");
        for (PolicyRuns r : results) {
            ObjectNode p = policies.putObject(r.policy().name());
            for (String m : measureNames(results)) {
                List<Double> values = values(r, m);
                Statistics.Summary s = Statistics.of(values);
                ObjectNode o = p.putObject(m);
                o.put("mean", round(s.mean()));
                ArrayNode ci = o.putArray("ci95");
                ci.add(round(s.lo()));
                ci.add(round(s.hi()));
                ArrayNode all = o.putArray("runs");
                values.forEach(v -> all.add(round(v)));
            }
        }
        return root;
    }

    public static List<Double> values(PolicyRuns r, String measure) {
        List<Double> values = new ArrayList<>();
        for (Simulation.Result x : r.runs()) {
            Double v = x.measures().get(measure);
            if (v != null) {
                values.add(v);
            }
        }
        return values;
    }

    /** Six significant digits: what a comparison needs, and stable to print. */
    static double round(double v) {
        if (!Double.isFinite(v) || v == 0) {
            return v;
        }
        return new java.math.BigDecimal(v).round(new java.math.MathContext(6)).doubleValue();
    }

    /** Problems the world met, each once, over all runs. */
    public static List<String> problems(List<PolicyRuns> results) {
        Set<String> all = new LinkedHashSet<>();
        results.forEach(r -> r.runs().forEach(x -> all.addAll(x.problems())));
        return List.copyOf(all);
    }

    /** A plain-text table of means and intervals, as the command prints it. */
    public static String table(List<PolicyRuns> results) {
        List<String> names = measureNames(results);
        int width = Math.max(24, names.stream().mapToInt(String::length).max().orElse(0) + 2);
        StringBuilder b = new StringBuilder(String.format(java.util.Locale.ROOT, "%-" + width + "s", "measure"));
        for (PolicyRuns r : results) {
            b.append(String.format(java.util.Locale.ROOT, "  %-28s", r.policy().name()));
        }
        b.append('\n');
        for (String m : names) {
            b.append(String.format(java.util.Locale.ROOT, "%-" + width + "s", m));
            for (PolicyRuns r : results) {
                Statistics.Summary s = Statistics.of(values(r, m));
                b.append(String.format(java.util.Locale.ROOT, "  %-28s", fmt(s.mean()) + " [" + fmt(s.lo()) + ", " + fmt(s.hi()) + "]"));
            }
            b.append('\n');
        }
        return b.toString();
    }

    static String fmt(double v) {
        if (!Double.isFinite(v)) {
            return String.valueOf(v);
        }
        double a = Math.abs(v);
        return String.format(java.util.Locale.ROOT, a >= 1000 || v == Math.rint(v) ? "%.0f" : a >= 10 ? "%.1f" : "%.3f", v);
    }
}
