package org.miron.cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.miron.runtime.Endpoints;
import org.miron.runtime.engine.Engine;
import org.miron.runtime.engine.EngineOptions;
import org.miron.runtime.engine.EngineStartException;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/** {@code miron engine --io model.io.json}: the adaptation engine. */
@Command(name = "engine", mixinStandardHelpOptions = true,
        description = "Run the adaptation engine on a generated name.io.json (+ .mzn/.dzn).",
        exitCodeListHeading = ExitCodes.HEADING,
        exitCodeList = { ExitCodes.STARTUP, ExitCodes.SIGTERM, ExitCodes.SIGINT })
public final class EngineCommand implements Callable<Integer> {
    @Option(names = "--io", required = true, paramLabel = "FILE", description = "the generated name.io.json")
    Path io;

    @Option(names = "--backend", description = "solver backend: native (in process), minizinc (the reference) or both "
            + "(cross-check every decision) (default: native; minizinc for an io.json without decision section)")
    String backend;

    @Option(names = "--minizinc", paramLabel = "PATH", description = "MiniZinc executable (default: ${DEFAULT-VALUE})")
    String minizinc = "minizinc";

    @Option(names = "--solver", description = "MiniZinc solver (default: ${DEFAULT-VALUE})")
    String solver = "gecode";

    @Option(names = "--time-limit", paramLabel = "MS", description = "solver time limit in ms, flattening included; 0: 2000 + 25 per varpoint (default: ${DEFAULT-VALUE})")
    long timeLimit = 0;

    @Option(names = "--decision-log", paramLabel = "FILE",
            description = "append-only JSON-lines decision log (default: ${DEFAULT-VALUE})")
    Path decisionLog = Path.of("miron-decisions.jsonl");

    @Option(names = "--status-interval", paramLabel = "MS",
            description = "re-publish miron.status at least this often (default: ${DEFAULT-VALUE})")
    long statusInterval = 5000;

    @Mixin
    BrokerEndpoints.BusIn busIn = new BrokerEndpoints.BusIn();

    @Mixin
    BrokerEndpoints.BusOut busOut = new BrokerEndpoints.BusOut();

    @Mixin
    BrokerEndpoints.Request request = new BrokerEndpoints.Request();

    @Override
    public Integer call() {
        EngineOptions o = new EngineOptions(io);
        o.backend = backend;
        o.minizinc = minizinc;
        o.solver = solver;
        o.timeLimitMs = timeLimit;
        o.decisionLog = decisionLog;
        o.statusIntervalMs = statusInterval;
        o.busIn = busIn.endpoint;
        o.busOut = busOut.endpoint;
        o.request = request.endpoint;
        Engine engine;
        try {
            engine = Engine.create(o).start();
        } catch (EngineStartException e) {
            System.err.println("miron engine: error: " + e.getMessage());
            return 2;
        }
        return UntilShutdown.run("engine", engine);
    }
}
