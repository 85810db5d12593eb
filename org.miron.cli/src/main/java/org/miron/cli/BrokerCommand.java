package org.miron.cli;

import java.util.concurrent.Callable;
import org.miron.runtime.broker.Broker;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;

/** {@code miron broker}: request path to the skill interface and the bus with last-value cache. */
@Command(name = "broker", mixinStandardHelpOptions = true,
        description = "Run the MIRoN broker: ROUTER/DEALER request path and XSUB/XPUB bus with last-value cache.",
        exitCodeListHeading = ExitCodes.HEADING,
        exitCodeList = { ExitCodes.STARTUP, ExitCodes.SIGTERM, ExitCodes.SIGINT })
public final class BrokerCommand implements Callable<Integer> {
    @Mixin
    BrokerSetup broker = new BrokerSetup();

    @Override
    public Integer call() {
        Broker running;
        try {
            running = new Broker(broker.endpoints(), broker.cacheFile).start();
        } catch (IllegalStateException e) {
            System.err.println("miron broker: error: " + e.getMessage());
            return 2;
        }
        return UntilShutdown.run("broker", running);
    }
}
