package org.miron.cli;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.miron.runtime.Endpoints;
import org.miron.runtime.broker.Broker;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/** {@code miron broker}: request path to the skill interface and the bus with last-value cache. */
@Command(name = "broker", mixinStandardHelpOptions = true,
        description = "Run the MIRoN broker: ROUTER/DEALER request path and XSUB/XPUB bus with last-value cache.",
        exitCodeListHeading = ExitCodes.HEADING,
        exitCodeList = { ExitCodes.STARTUP, ExitCodes.SIGTERM, ExitCodes.SIGINT })
public final class BrokerCommand implements Callable<Integer> {
    @Mixin
    BrokerEndpoints.Request request = new BrokerEndpoints.Request();

    @Option(names = "--skill", description = "skill interface REP the DEALER connects to (default: ${DEFAULT-VALUE})")
    String skill = Endpoints.DEFAULT_SKILL;

    @Mixin
    BrokerEndpoints.BusIn busIn = new BrokerEndpoints.BusIn();

    @Mixin
    BrokerEndpoints.BusOut busOut = new BrokerEndpoints.BusOut();

    @Option(names = "--cache-file", paramLabel = "FILE",
            description = "snapshot of the last-value cache, written every 0.5 s when it changed and reloaded on start")
    Path cacheFile;

    @Override
    public Integer call() {
        Broker broker;
        try {
            broker = new Broker(new Endpoints(request.endpoint, skill, Endpoints.DEFAULT_SKILL_EVENTS, busIn.endpoint,
                    busOut.endpoint), cacheFile).start();
        } catch (IllegalStateException e) {
            System.err.println("miron broker: error: " + e.getMessage());
            return 2;
        }
        return UntilShutdown.run("broker", broker);
    }
}
