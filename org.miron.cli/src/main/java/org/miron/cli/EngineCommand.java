package org.miron.cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;
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

    @Mixin
    EngineSolving solving = new EngineSolving();

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
        EngineOptions o = solving.applyTo(new EngineOptions(io));
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
