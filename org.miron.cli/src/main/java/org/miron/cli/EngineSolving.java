package org.miron.cli;

import java.nio.file.Path;
import org.miron.runtime.engine.EngineOptions;
import picocli.CommandLine.Option;

/** The engine's solving options, shared by {@code miron engine} and {@code miron run} as a picocli mixin. */
public final class EngineSolving {
    @Option(names = "--backend", description = "the engine's solver backend: native (in process), minizinc (the reference) "
            + "or both (cross-check every decision) (default: native; minizinc for an io.json without decision section)")
    String backend;

    @Option(names = "--minizinc", paramLabel = "PATH", description = "MiniZinc executable (default: ${DEFAULT-VALUE})")
    String minizinc = "minizinc";

    @Option(names = "--solver", description = "MiniZinc solver (default: ${DEFAULT-VALUE})")
    String solver = "gecode";

    @Option(names = "--time-limit", paramLabel = "MS",
            description = "solver time limit in ms, flattening included; 0: 2000 + 25 per varpoint (default: ${DEFAULT-VALUE})")
    long timeLimit = 0;

    @Option(names = "--decision-log", paramLabel = "FILE",
            description = "the engine's append-only JSON-lines decision log (default: ${DEFAULT-VALUE})")
    Path decisionLog = Path.of("miron-decisions.jsonl");

    /** Sets these options on the engine's; returns them. */
    EngineOptions applyTo(EngineOptions o) {
        o.backend = backend;
        o.minizinc = minizinc;
        o.solver = solver;
        o.timeLimitMs = timeLimit;
        o.decisionLog = decisionLog;
        return o;
    }
}
