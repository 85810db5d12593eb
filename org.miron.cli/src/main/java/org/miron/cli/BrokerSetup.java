package org.miron.cli;

import java.nio.file.Path;
import org.miron.runtime.Endpoints;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/** What a broker binds and keeps, shared by {@code miron broker} and {@code miron run} as a picocli mixin. */
public final class BrokerSetup {
    @Mixin
    BrokerEndpoints.Request request = new BrokerEndpoints.Request();

    @Option(names = "--skill", description = "skill interface REP the broker's DEALER connects to (default: ${DEFAULT-VALUE})")
    String skill = Endpoints.DEFAULT_SKILL;

    @Mixin
    BrokerEndpoints.BusIn busIn = new BrokerEndpoints.BusIn();

    @Mixin
    BrokerEndpoints.BusOut busOut = new BrokerEndpoints.BusOut();

    @Option(names = "--cache-file", paramLabel = "FILE",
            description = "snapshot of the broker's last-value cache, written every 0.5 s when it changed and reloaded on start")
    Path cacheFile;

    Endpoints endpoints() {
        return new Endpoints(request.endpoint, skill, Endpoints.DEFAULT_SKILL_EVENTS, busIn.endpoint, busOut.endpoint);
    }
}
