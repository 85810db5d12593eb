package org.miron.runtime.sim;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.miron.runtime.Json;
import org.miron.runtime.requirement.ClopperPearson;
import org.miron.runtime.requirement.RequirementModel;
import org.miron.runtime.requirement.RequirementResult;
import org.miron.runtime.requirement.Sprt;
import org.miron.runtime.requirement.Verdict;

/**
 * Statistical model checking of a model's requirements on the simulator (docs/requirements.md,
 * "miron verify"): every run of every policy is monitored; per requirement and policy, the runs that
 * violated it, the violation probability's exact 95 % interval and the first counterexample. A
 * probabilistic requirement is decided by Wald's SPRT over the runs in seed order. Runs go in
 * parallel, results are taken in seed order, and the sequential test stops on the prefix it has
 * seen, so the same seed gives the same answer whatever the threads did.
 */
public final class Verification {
    /**
     * @param runs         runs per policy; 0 for a sequential check: runs until every probabilistic
     *                     requirement is decided, at most {@code maxRuns}
     * @param confidence   the SPRT's 1 − α (= 1 − β)
     * @param indifference the half-width δ of its indifference region
     */
    public record Options(int runs, int maxRuns, double confidence, double indifference, long seed, long durationMs,
            int threads) {
        boolean sequential() {
            return runs <= 0;
        }
    }

    /** The first run that violated a requirement: which run (1-based), its seed, when, and the values then. */
    public record Counterexample(int run, long seed, long timeMs, long detectedMs, Map<String, Object> values) {
    }

    /**
     * One requirement under one policy. {@code sprt} is null unless it is probabilistic;
     * {@code neverValued}: the signals that had no value in some run not evaluated, in the order read.
     */
    public record Check(RequirementModel.Requirement requirement, int runs, int violated, int open, int notEvaluated,
            ClopperPearson.Interval interval, String verdict, Counterexample first, Sprt sprt, List<String> neverValued) {
        public boolean holds() {
            return verdict.equals("holds");
        }
    }

    public record PolicyResult(Policy policy, List<Simulation.Result> runs, List<Check> checks) {
    }

    private Verification() {
    }

    public static List<PolicyResult> run(Setup setup, List<Policy> policies, Options o) throws InterruptedException {
        ExecutorService pool = Executors.newFixedThreadPool(Math.max(1, o.threads()), r -> {
            Thread t = new Thread(r, "verify");
            t.setDaemon(true);
            return t;
        });
        try {
            List<PolicyResult> out = new ArrayList<>();
            for (Policy p : policies) {
                out.add(policy(setup, p, o, pool));
            }
            return out;
        } finally {
            pool.shutdownNow();
        }
    }

    private static PolicyResult policy(Setup setup, Policy p, Options o, ExecutorService pool) throws InterruptedException {
        List<RequirementModel.Requirement> reqs = setup.requirements().requirements();
        List<Sprt> tests = new ArrayList<>();
        for (RequirementModel.Requirement r : reqs) {
            tests.add(r.probability() == null ? null
                    : new Sprt(r.probability(), o.indifference(), 1 - o.confidence(), 1 - o.confidence()));
        }
        int limit = o.sequential() ? o.maxRuns() : o.runs();
        int batch = o.sequential() ? Math.max(1, o.threads()) : limit;
        List<Simulation.Result> runs = new ArrayList<>();
        while (runs.size() < limit && !(o.sequential() && decided(tests))) {
            List<Future<Simulation.Result>> futures = new ArrayList<>();
            for (int i = runs.size(); i < Math.min(limit, runs.size() + batch); i++) {
                long seed = o.seed() + i;
                futures.add(pool.submit(() -> new Simulation(setup, p, seed, o.durationMs(), -1).run()));
            }
            for (Future<Simulation.Result> f : futures) {
                Simulation.Result r;
                try {
                    r = f.get();
                } catch (ExecutionException e) {
                    Throwable c = e.getCause();
                    throw c instanceof RuntimeException re ? re : new IllegalStateException(c);
                }
                if (o.sequential() && decided(tests)) {
                    break; // later runs are not needed: the answer is the prefix's
                }
                runs.add(r);
                for (int k = 0; k < reqs.size(); k++) {
                    if (tests.get(k) != null) {
                        tests.get(k).add(r.requirements().get(k).verdict() != Verdict.VIOLATED);
                    }
                }
            }
        }
        List<Check> checks = new ArrayList<>();
        for (int k = 0; k < reqs.size(); k++) {
            checks.add(check(reqs.get(k), k, runs, tests.get(k), o.seed()));
        }
        return new PolicyResult(p, runs, checks);
    }

    private static boolean decided(List<Sprt> tests) {
        boolean any = false;
        for (Sprt t : tests) {
            if (t != null) {
                any = true;
                if (t.decision() == Sprt.Decision.UNDECIDED) {
                    return false;
                }
            }
        }
        return any;
    }

    private static Check check(RequirementModel.Requirement req, int k, List<Simulation.Result> runs, Sprt sprt, long seed) {
        int violated = 0;
        int open = 0;
        int notEvaluated = 0;
        Set<String> neverValued = new LinkedHashSet<>();
        Counterexample first = null;
        for (int i = 0; i < runs.size(); i++) {
            RequirementResult r = runs.get(i).requirements().get(k);
            switch (r.verdict()) {
                case VIOLATED -> {
                    violated++;
                    if (first == null) {
                        first = new Counterexample(i + 1, seed + i, r.firstViolation().timeMs(), r.firstViolation().detectedMs(),
                                r.firstViolation().values());
                    }
                }
                case OPEN -> open++;
                case NOT_EVALUATED -> {
                    notEvaluated++;
                    neverValued.addAll(r.neverValued());
                }
                default -> {
                }
            }
        }
        ClopperPearson.Interval ci = ClopperPearson.of(violated, Math.max(1, runs.size()), 0.95);
        String verdict;
        if (notEvaluated == runs.size()) {
            verdict = "not-evaluated";
        } else if (sprt != null) {
            verdict = switch (sprt.decision()) {
                case HOLDS -> "holds";
                case FAILS -> "fails";
                default -> "undecided";
            };
        } else {
            verdict = violated > 0 ? "violated" : "holds";
        }
        return new Check(req, runs.size(), violated, open, notEvaluated, ci, verdict, first, sprt, List.copyOf(neverValued));
    }

    /** Each policy's coverage over the runs it made (a sequential check: as many as its test needed). */
    public static List<CoverageTable.Column> coverage(List<PolicyResult> results) {
        return CoverageTable.of(results.stream().map(r -> new Comparison.PolicyRuns(r.policy(), r.runs())).toList());
    }

    /** True when every requirement holds under every policy. */
    public static boolean allHold(List<PolicyResult> results) {
        return results.stream().allMatch(r -> r.checks().stream().allMatch(Check::holds));
    }

    /**
     * {@code {"requirements": {NAME: {POLICY: {"runs", "violated", "verdict", "violationProbability",
     * "firstViolation"}}}, "policies": the measures as miron simulate writes them}} plus the settings.
     */
    public static ObjectNode summary(List<PolicyResult> results, Options o) {
        ObjectNode root = Json.object();
        root.put("durationS", o.durationMs() / 1000.0);
        root.put("seed", o.seed());
        if (o.sequential()) {
            root.put("confidence", o.confidence());
            root.put("indifference", o.indifference());
            root.put("maxRuns", o.maxRuns());
        } else {
            root.put("runs", o.runs());
        }
        ObjectNode reqs = root.putObject("requirements");
        for (PolicyResult r : results) {
            for (Check c : r.checks()) {
                ObjectNode per = reqs.has(c.requirement().name()) ? (ObjectNode) reqs.get(c.requirement().name())
                        : reqs.putObject(c.requirement().name());
                ObjectNode x = per.putObject(r.policy().name());
                x.put("runs", c.runs());
                x.put("violated", c.violated());
                x.put("open", c.open());
                x.put("notEvaluated", c.notEvaluated());
                x.put("verdict", c.verdict());
                ObjectNode p = x.putObject("violationProbability");
                p.put("estimate", Comparison.round(c.interval().estimate()));
                ArrayNode ci = p.putArray("ci95");
                ci.add(Comparison.round(c.interval().lo()));
                ci.add(Comparison.round(c.interval().hi()));
                if (c.sprt() != null) {
                    ObjectNode s = x.putObject("sequentialTest");
                    s.put("probability", c.requirement().probability());
                    ArrayNode region = s.putArray("indifference");
                    region.add(Comparison.round(c.sprt().lower()));
                    region.add(Comparison.round(c.sprt().upper()));
                    s.put("alpha", Comparison.round(1 - o.confidence()));
                    s.put("beta", Comparison.round(1 - o.confidence()));
                    s.put("runsUsed", c.sprt().runs());
                }
                if (c.first() == null) {
                    x.putNull("firstViolation");
                } else {
                    ObjectNode f = x.putObject("firstViolation");
                    f.put("run", c.first().run());
                    f.put("seed", c.first().seed());
                    f.put("time", c.first().timeMs() / 1000.0);
                    f.put("detected", c.first().detectedMs() / 1000.0);
                    f.set("values", Json.MAPPER.valueToTree(c.first().values()));
                }
            }
        }
        List<Comparison.PolicyRuns> measured = results.stream().map(r -> new Comparison.PolicyRuns(r.policy(), r.runs())).toList();
        root.set("policies", Comparison.summary(measured, 0, o.seed(), o.durationMs()).get("policies"));
        return root;
    }

    /** The console's table: a row per requirement and policy, the first counterexample under it. */
    public static String table(List<PolicyResult> results) {
        int width = 12;
        int pw = 8;
        for (PolicyResult r : results) {
            pw = Math.max(pw, r.policy().name().length());
            for (Check c : r.checks()) {
                width = Math.max(width, c.requirement().name().length());
            }
        }
        String row = "%-" + width + "s  %-" + pw + "s  %5s  %8s  %-24s  %s%n";
        StringBuilder b = new StringBuilder(String.format(Locale.ROOT, row, "requirement", "policy", "runs", "violated",
                "P(violation) [95 % CI]", "verdict"));
        List<String> names = results.isEmpty() ? List.of()
                : results.get(0).checks().stream().map(c -> c.requirement().name()).toList();
        for (int k = 0; k < names.size(); k++) {
            for (PolicyResult r : results) {
                Check c = r.checks().get(k);
                b.append(String.format(Locale.ROOT, row, names.get(k), r.policy().name(), c.runs(), c.violated(),
                        String.format(Locale.ROOT, "%.3f [%.3f, %.3f]", c.interval().estimate(), c.interval().lo(), c.interval().hi()),
                        verdictText(c)));
                if (c.first() != null) {
                    b.append("  first counterexample: run ").append(c.first().run()).append(" (seed ").append(c.first().seed())
                            .append(") at ").append(clock(c.first().timeMs()));
                    if (c.first().detectedMs() - c.first().timeMs() >= 1000) {
                        b.append(" (known ").append(clock(c.first().detectedMs())).append(")");
                    }
                    b.append(": ").append(org.miron.runtime.requirement.RequirementEvent.format(c.first().values())).append('\n');
                }
            }
        }
        return b.toString();
    }

    /** The verdict as the table says it: with the sequential test's runs, open ends and runs never evaluated. */
    public static String verdictText(Check c) {
        String v = switch (c.verdict()) {
            case "not-evaluated" -> "never evaluated: no value for " + String.join(", ", c.neverValued());
            default -> c.verdict();
        };
        if (c.sprt() != null) {
            v += c.sprt().decision() == Sprt.Decision.UNDECIDED ? " after " + c.sprt().runs() + (c.sprt().runs() == 1 ? " run" : " runs")
                    : " (SPRT, " + c.sprt().runs() + " runs)";
        }
        if (c.open() > 0 && c.violated() < c.runs()) {
            v += ", open at the end in " + c.open();
        }
        if (c.notEvaluated() > 0 && !c.verdict().equals("not-evaluated")) {
            v += ", never evaluated in " + c.notEvaluated() + " (no value for " + String.join(", ", c.neverValued()) + ")";
        }
        return v;
    }

    /** {@code 1h02m03.4s}: where in a shift a counterexample lies. */
    static String clock(long ms) {
        long s = ms / 1000;
        String tenth = String.valueOf((ms % 1000) / 100);
        if (s < 60) {
            return s + "." + tenth + " s";
        }
        long h = s / 3600;
        long m = (s % 3600) / 60;
        return (h > 0 ? h + "h" + String.format(Locale.ROOT, "%02d", m) + "m" : m + "m")
                + String.format(Locale.ROOT, "%02d", s % 60) + "." + tenth + "s";
    }
}
