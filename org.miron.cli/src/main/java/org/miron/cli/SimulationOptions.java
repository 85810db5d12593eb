package org.miron.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.miron.runtime.sim.Policy;

import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** The options `miron simulate` and `miron verify` share (a picocli mixin): the model, its world, the runs' length, seeds, threads and coverage. */
final class SimulationOptions {
    @Parameters(index = "0", paramLabel = "MODEL.miron", description = "the MIRoN model")
    Path model;

    @Option(names = "--world", required = true, paramLabel = "FILE", description = "the world file (docs/simulator.md)")
    Path world;

    @Option(names = "--duration", paramLabel = "TIME", defaultValue = "8h",
            description = "simulated time per run, e.g. 30m, 8h (default: ${DEFAULT-VALUE})")
    String duration;

    @Option(names = "--seed", paramLabel = "S", defaultValue = "1",
            description = "run i of every policy uses seed S+i; the same seed gives the same output (default: ${DEFAULT-VALUE})")
    long seed;

    @Option(names = "--threads", paramLabel = "N", description = "parallel runs (default: the number of cores)")
    Integer threads;

    @Option(names = "--coverage",
            description = "also report, over each policy's runs, how often every node of the woven tree ran and ended SUCCESS/FAILURE, "
                    + "each enum variant's share of time and how often each rule applied (docs/simulator.md, \"Coverage\")")
    boolean coverage;

    @Option(names = "--min-coverage", paramLabel = "PCT",
            description = "exit 1 when a policy's runs cover less than PCT %% of those items (implies --coverage)")
    Double minCoverage;

    /** Whether the coverage is reported: asked for, or needed by the gate. */
    boolean coverage() {
        return coverage || minCoverage != null;
    }

    /** The policies named with --policy, or these defaults; a bad one is an IllegalArgumentException naming it. */
    static List<Policy> policies(List<String> named, List<String> defaults) {
        List<Policy> parsed = new ArrayList<>();
        for (String p : named.isEmpty() ? defaults : named) {
            parsed.add(Policy.parse(p));
        }
        return parsed;
    }

    /** {@code FILE: error: no such file} for the model or the world when one is missing, else null. */
    String missingFile() {
        return !Files.isRegularFile(model) ? model + ": error: no such file"
                : !Files.isRegularFile(world) ? world + ": error: no such file" : null;
    }

    /** {@code intralogistics.miron in world.json}: what the console, the reports and their titles call the run. */
    String title() {
        return model.getFileName() + " in " + world.getFileName();
    }

    int cores() {
        return threads != null ? Math.max(1, threads) : Runtime.getRuntime().availableProcessors();
    }
}
