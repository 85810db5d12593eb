package org.miron.runtime;

/**
 * The ZeroMQ endpoints of one MIRoN installation. Defaults are the original MIRoN ports on
 * loopback; tests build their own set on free ports.
 *
 * @param request     broker ROUTER, where REQ clients (engine, BT executor) send skill queries
 * @param skill       skill interface REP, the broker DEALER connects here
 * @param skillEvents skill interface PUB, skill results
 * @param busIn       broker XSUB, publishers connect here
 * @param busOut      broker XPUB, subscribers connect here
 */
public record Endpoints(String request, String skill, String skillEvents, String busIn, String busOut) {

    public static final String DEFAULT_REQUEST = "tcp://127.0.0.1:5556";
    public static final String DEFAULT_SKILL = "tcp://127.0.0.1:5557";
    public static final String DEFAULT_SKILL_EVENTS = "tcp://127.0.0.1:5558";
    public static final String DEFAULT_BUS_IN = "tcp://127.0.0.1:5560";
    public static final String DEFAULT_BUS_OUT = "tcp://127.0.0.1:5561";

    public static Endpoints defaults() {
        return new Endpoints(DEFAULT_REQUEST, DEFAULT_SKILL, DEFAULT_SKILL_EVENTS, DEFAULT_BUS_IN, DEFAULT_BUS_OUT);
    }

    /** Loopback endpoints on the given ports (request, skill, skillEvents, busIn, busOut). */
    public static Endpoints loopback(int request, int skill, int skillEvents, int busIn, int busOut) {
        return new Endpoints(tcp(request), tcp(skill), tcp(skillEvents), tcp(busIn), tcp(busOut));
    }

    /**
     * Loopback endpoints on five distinct ports free right now, below the ephemeral range
     * ({@link FreePorts}): for a one-JVM run that must not clash with others.
     */
    public static Endpoints freeLoopback() {
        int[] ports = FreePorts.take(5);
        return loopback(ports[0], ports[1], ports[2], ports[3], ports[4]);
    }

    private static String tcp(int port) {
        return "tcp://127.0.0.1:" + port;
    }
}
