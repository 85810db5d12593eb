package org.miron.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.logging.Level;
import java.util.logging.Logger;

import org.miron.cli.demo.SimulationReport;
import org.miron.runtime.sim.Comparison;
import org.miron.runtime.sim.CoverageTable;
import org.miron.runtime.sim.Durations;
import org.miron.runtime.sim.Policy;
import org.miron.runtime.sim.Setup;
import org.miron.runtime.sim.Statistics;

import com.fasterxml.jackson.databind.node.ObjectNode;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * `miron simulate`: runs a MIRoN model closed-loop against a world file on a virtual clock, once per
 * seed and policy, and compares the policies' measures with confidence intervals (docs/simulator.md).
 */
@Command(name = "simulate", mixinStandardHelpOptions = true,
        description = "Simulates a MIRoN model's robot in a world (a JSON file: state, skills' durations and effects, "
                + "random processes, published contexts, measures) on a virtual clock, without a broker, and compares "
                + "policies: adaptive (the model), preset (nothing adapts), fixed:vp=value,... Writes OUT/summary.json "
                + "and OUT/report.html.",
        exitCodeListHeading = "Exit codes:%n",
        exitCodeList = { "0:simulated", "1:the model or the world file has errors, or a policy's coverage is below --min-coverage",
            "2:usage error" })
public class SimulateCommand implements Callable<Integer> {
    @Mixin
    SimulationOptions run = new SimulationOptions();

    @Option(names = "--runs", paramLabel = "N", defaultValue = "10", description = "runs per policy (default: ${DEFAULT-VALUE})")
    int runs;

    @Option(names = "--policy", paramLabel = "POLICY",
            description = "adaptive, preset or fixed:vp=value,...; repeatable (default: adaptive and preset)")
    List<String> policies = new ArrayList<>();

    @Option(names = "--out", paramLabel = "DIR", defaultValue = "miron-simulate",
            description = "where summary.json, report.html and the generated model go (default: ${DEFAULT-VALUE})")
    Path out;

    @Option(names = "--timeline", paramLabel = "TIME", defaultValue = "30m",
            description = "how much of the first run of each policy the report's timelines show (default: ${DEFAULT-VALUE})")
    String timeline;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        PrintWriter console = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        long durationMs;
        long timelineMs;
        List<Policy> parsed;
        try {
            durationMs = Durations.parseMs(run.duration);
            timelineMs = Durations.parseMs(timeline);
            parsed = SimulationOptions.policies(policies, List.of("adaptive", "preset"));
        } catch (IllegalArgumentException e) {
            return usage(e.getMessage());
        }
        if (runs < 1 || durationMs <= 0) {
            return usage("--runs and --duration must be positive");
        }
        String wrong = CoverageOutput.check(run);
        if (wrong != null) {
            return usage(wrong);
        }
        if (run.missingFile() != null) {
            return usage(run.missingFile());
        }
        SimulationModel.Loaded loaded = SimulationModel.load(run.model, run.world, out, parsed, err, "simulate", 1);
        if (loaded.setup() == null) {
            return loaded.status();
        }
        Logger.getLogger("").setLevel(Level.SEVERE); // the solver's per-decision logs are not the user's concern here
        Setup setup = loaded.setup();
        int cores = run.cores();
        console.println("MIRoN simulate: " + run.title() + ", " + runs + " run(s) of "
                + run.duration + " per policy, seed " + run.seed);
        console.flush();
        long started = System.nanoTime();
        List<Comparison.PolicyRuns> results;
        try {
            results = Comparison.run(setup, parsed, runs, run.seed, durationMs, timelineMs, cores);
        } catch (RuntimeException e) { // an expression that cannot run on the values it met (a script error)
            err.println("miron simulate: error: a run stopped: " + e.getMessage());
            err.flush();
            return 1;
        }
        double wall = (System.nanoTime() - started) / 1e9;
        console.println();
        console.print(Comparison.table(results));
        console.println();
        console.println("(mean [" + Statistics.INTERVAL + "] over " + runs + " run(s); metric:* are the RoQME estimates' time averages)");
        for (String problem : Comparison.problems(results)) {
            console.println("world: " + problem);
        }
        ObjectNode summary = Comparison.summary(results, runs, run.seed, durationMs);
        List<CoverageTable.Column> coverage = Comparison.coverage(results);
        boolean covered = CoverageOutput.report(run, coverage, console, err, "simulate", summary);
        SimulationModel.writeSummary(out, summary);
        new SimulationReport(run.title(), results, setup.world(), timelineMs)
                .coverage(run.coverage() ? coverage : null).write(out.resolve("report.html"));
        SimulationModel.printWritten(out, console);
        double simulated = durationMs / 1000.0 * runs * parsed.size();
        err.printf(java.util.Locale.ROOT, "miron simulate: %.0f s simulated in %.1f s on %d thread(s) (%.0fx real time)%n",
                simulated, wall, cores, simulated / Math.max(wall, 1e-9));
        err.flush();
        return covered ? 0 : 1;
    }

    private int usage(String message) {
        spec.commandLine().getErr().println(message);
        spec.commandLine().getErr().flush();
        return 2;
    }
}
