package org.miron.runtime.engine;

import java.nio.file.Path;
import org.miron.runtime.Endpoints;
import org.miron.runtime.bus.BusLink;

/** Engine settings; defaults are the MIRoN loopback endpoints and the native backend. */
public final class EngineOptions {
    public Path ioJson;
    public String busIn = Endpoints.DEFAULT_BUS_IN;
    public String busOut = Endpoints.DEFAULT_BUS_OUT;
    /** Null: sockets to {@link #busIn} / {@link #busOut}; a broker's {@code local()} in its process. */
    public BusLink bus;
    public String request = Endpoints.DEFAULT_REQUEST;
    /** Null: native, or minizinc for an io.json without decision section ({@link Backends#create}). */
    public String backend;
    public String minizinc = "minizinc";
    public String solver = "gecode";
    /** Solver time limit; 0: automatic, 2 s + 25 ms per varpoint (MiniZincBackend.autoTimeLimitMs). */
    public long timeLimitMs = 0;
    /** Null: no decision log. */
    public Path decisionLog;
    public long ackTimeoutMs = 1000;
    public long backoffMinMs = 200;
    public long backoffMaxMs = 5000;
    /** miron.status is also re-published this often when nothing happens (a heartbeat). */
    public long statusIntervalMs = 5000;
    /** After a solver timeout or crash the same inputs are solved again after this delay, doubling up to the max. */
    public long solveRetryMinMs = 500;
    public long solveRetryMaxMs = 10_000;
    /**
     * Longest wait for the broker's last-value replay before the first solve (settle time); the
     * replay normally completes within milliseconds, this only bounds the wait without a broker.
     */
    public long settleMs = 1000;

    public EngineOptions(Path ioJson) {
        this.ioJson = ioJson;
    }

    public EngineOptions endpoints(Endpoints e) {
        busIn = e.busIn();
        busOut = e.busOut();
        request = e.request();
        return this;
    }
}
