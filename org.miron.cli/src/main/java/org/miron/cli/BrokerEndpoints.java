package org.miron.cli;

import org.miron.runtime.Endpoints;

import picocli.CommandLine.Option;

/**
 * The broker endpoints the runtime commands share, as picocli mixins: the broker binds them, the
 * other components connect to them. One class per option, since not every command needs all three.
 */
public final class BrokerEndpoints {

    private BrokerEndpoints() {
    }

    /** {@code --bus-in}: where publishers send (the broker's XSUB). */
    public static final class BusIn {
        @Option(names = "--bus-in", paramLabel = "ENDPOINT",
                description = "the broker's XSUB, where publishers send (default: ${DEFAULT-VALUE})")
        public String endpoint = Endpoints.DEFAULT_BUS_IN;
    }

    /** {@code --bus-out}: where subscribers listen (the broker's XPUB, with the last-value cache). */
    public static final class BusOut {
        @Option(names = "--bus-out", paramLabel = "ENDPOINT",
                description = "the broker's XPUB, where subscribers listen (default: ${DEFAULT-VALUE})")
        public String endpoint = Endpoints.DEFAULT_BUS_OUT;
    }

    /** {@code --request}: the request path to the skill interface (the broker's ROUTER). */
    public static final class Request {
        @Option(names = "--request", paramLabel = "ENDPOINT",
                description = "the broker's ROUTER, the request path to the skill interface (default: ${DEFAULT-VALUE})")
        public String endpoint = Endpoints.DEFAULT_REQUEST;
    }
}
