package org.miron.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.logging.Level;
import java.util.logging.Logger;

import org.miron.cli.demo.VerifyReport;
import org.miron.runtime.sim.CoverageTable;
import org.miron.runtime.sim.Durations;
import org.miron.runtime.sim.Policy;
import org.miron.runtime.sim.Setup;
import org.miron.runtime.sim.Verification;

import com.fasterxml.jackson.databind.node.ObjectNode;

import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * `miron verify`: the model's requirements checked over simulated missions (docs/requirements.md):
 * the simulator of `miron simulate` with a monitor per requirement on every run.
 */
@Command(name = "verify", mixinStandardHelpOptions = true,
        description = "Checks a MIRoN model's requirements over simulated missions: runs the simulator (as miron simulate) "
                + "with a monitor per requirement on every run and prints, per requirement and policy, the runs that violated "
                + "it, the violation probability with its exact 95 %% interval (Clopper-Pearson) and the first counterexample; "
                + "a probabilistic requirement (with probability >= p) is decided by Wald's sequential test. Writes "
                + "OUT/summary.json and OUT/report.html.",
        exitCodeListHeading = "Exit codes:%n",
        exitCodeList = { "0:every requirement holds in every run of every policy (a probabilistic one: the test says it holds)",
            "1:a requirement is violated, a probabilistic one fails or stays undecided, or one was never evaluated; "
                    + "or a policy's coverage is below --min-coverage",
            "2:usage error, a model with errors or without requirements" })
public class VerifyCommand implements Callable<Integer> {
    @Mixin
    SimulationOptions run = new SimulationOptions();

    @Option(names = "--runs", paramLabel = "N",
            description = "runs per policy (default: 10; with a probabilistic requirement and no --runs, the sequential test decides)")
    Integer runs;

    @Option(names = "--confidence", paramLabel = "C",
            description = "the sequential test's confidence 1 - alpha = 1 - beta (default: 0.95); runs until every "
                    + "probabilistic requirement is decided")
    Double confidence;

    @Option(names = "--indifference", paramLabel = "D", defaultValue = "0.05",
            description = "half-width of the sequential test's indifference region around p (default: ${DEFAULT-VALUE})")
    double indifference;

    @Option(names = "--max-runs", paramLabel = "N",
            description = "most runs per policy of a sequential check (default: " + DEFAULT_MAX_RUNS + ")")
    Integer maxRuns;
    private static final int DEFAULT_MAX_RUNS = 1000;

    @Option(names = "--policy", paramLabel = "POLICY",
            description = "adaptive, preset or fixed:vp=value,...; repeatable (default: adaptive)")
    List<String> policies = new ArrayList<>();

    @Option(names = "--out", paramLabel = "DIR", defaultValue = "miron-verify",
            description = "where summary.json, report.html and the generated model go (default: ${DEFAULT-VALUE})")
    Path out;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        PrintWriter console = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        long durationMs;
        List<Policy> parsed;
        try {
            durationMs = Durations.parseMs(run.duration);
            parsed = SimulationOptions.policies(policies, List.of("adaptive"));
        } catch (IllegalArgumentException e) {
            return usage(e.getMessage());
        }
        if (durationMs <= 0 || (runs != null && runs < 1) || (maxRuns != null && maxRuns < 1)) {
            return usage("miron verify: error: --duration, --runs and --max-runs must be positive");
        }
        if (runs != null && maxRuns != null) {
            return usage("miron verify: error: --runs and --max-runs exclude each other: --max-runs bounds a sequential "
                    + "check, --runs makes that many runs");
        }
        int most = maxRuns == null ? DEFAULT_MAX_RUNS : maxRuns;
        if (runs != null && confidence != null) {
            return usage("miron verify: error: --runs and --confidence exclude each other: a fixed number of runs, or "
                    + "as many as the sequential test needs");
        }
        if (confidence != null && !(confidence > 0.5 && confidence < 1)) {
            return usage("miron verify: error: --confidence must lie in (0.5, 1), e.g. 0.95");
        }
        if (!(indifference > 0 && indifference < 0.5)) {
            return usage("miron verify: error: --indifference must lie in (0, 0.5), e.g. 0.05");
        }
        String wrong = CoverageOutput.check(run);
        if (wrong != null) {
            return usage("miron verify: error: " + wrong);
        }
        if (run.missingFile() != null) {
            return usage(run.missingFile());
        }
        SimulationModel.Loaded loaded = SimulationModel.load(run.model, run.world, out, parsed, err, "verify", 2);
        if (loaded.setup() == null) {
            return loaded.status();
        }
        Setup setup = loaded.setup();
        if (setup.requirements() == null || setup.requirements().requirements().isEmpty()) {
            return usage(run.model + ": error: the model states no requirement: nothing to verify (docs/requirements.md)");
        }
        boolean probabilistic = setup.requirements().requirements().stream().anyMatch(r -> r.probability() != null);
        if (confidence != null && !probabilistic) {
            return usage("miron verify: error: --confidence decides probabilistic requirements (with probability >= p), "
                    + "and the model states none: use --runs");
        }
        boolean sequential = confidence != null || (runs == null && probabilistic);
        int cores = run.cores();
        Verification.Options options = new Verification.Options(sequential ? 0 : runs == null ? 10 : runs, most,
                confidence == null ? 0.95 : confidence, indifference, run.seed, durationMs, cores);
        Logger.getLogger("").setLevel(Level.SEVERE); // the solver's per-decision logs are not the user's concern here
        console.println("MIRoN verify: " + run.title() + ", "
                + setup.requirements().requirements().size() + " requirement(s), "
                + (sequential ? "runs of " + run.duration + " until the sequential test decides (at most " + most + ")"
                        : options.runs() + " run(s) of " + run.duration) + " per policy, seed " + run.seed);
        console.flush();
        long started = System.nanoTime();
        List<Verification.PolicyResult> results;
        try {
            results = Verification.run(setup, parsed, options);
        } catch (RuntimeException e) { // an expression that cannot run on the values it met (a script error)
            err.println("miron verify: error: a run stopped: " + e.getMessage());
            err.flush();
            return 1;
        }
        double wall = (System.nanoTime() - started) / 1e9;
        console.println();
        console.print(Verification.table(results));
        console.println();
        console.println("(P(violation): the share of runs that violated the requirement, with its exact 95 % interval "
                + "(Clopper-Pearson); probabilistic requirements by Wald's SPRT, alpha = beta = "
                + String.format(Locale.ROOT, "%.3g", 1 - options.confidence()) + ", indifference +/- " + indifference + ")");
        ObjectNode summary = Verification.summary(results, options);
        List<CoverageTable.Column> coverage = Verification.coverage(results);
        boolean covered = CoverageOutput.report(run, coverage, console, err, "verify", summary);
        SimulationModel.writeSummary(out, summary);
        new VerifyReport(run.title(), setup, results, options, ModelNames.of(run.model.toFile()))
                .coverage(run.coverage() ? coverage : null).write(out.resolve("report.html"));
        SimulationModel.printWritten(out, console);
        int total = results.stream().mapToInt(r -> r.runs().size()).sum();
        err.printf(Locale.ROOT, "miron verify: %d run(s) of %s in %.1f s on %d thread(s)%n", total, run.duration, wall, cores);
        err.flush();
        return Verification.allHold(results) && covered ? 0 : 1;
    }

    private int usage(String message) {
        spec.commandLine().getErr().println(message);
        spec.commandLine().getErr().flush();
        return 2;
    }
}
