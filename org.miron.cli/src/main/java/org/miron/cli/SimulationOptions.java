package org.miron.cli;

import java.nio.file.Path;

import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** The options `miron simulate` and `miron verify` share (a picocli mixin): the model, its world, the runs' length, seeds and threads. */
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

    int cores() {
        return threads != null ? Math.max(1, threads) : Runtime.getRuntime().availableProcessors();
    }
}
