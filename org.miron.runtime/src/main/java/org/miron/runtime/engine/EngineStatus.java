package org.miron.runtime.engine;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.Map;
import java.util.TreeMap;
import org.miron.runtime.Json;

/**
 * Health counters and the last problem, published as {@code miron.status}. Thread-safe: the bus
 * thread counts bad input, the solve loop solver outcomes, the parameter sender its retries.
 */
public final class EngineStatus {
    private final String model;
    private final String backend;
    private final Map<String, Long> counters = new TreeMap<>();
    private String lastOutcome = "STARTING";
    private String lastErrorKind;
    private String lastErrorMessage;
    private long lastErrorTime;

    public EngineStatus(String model, String backend) {
        this.model = model;
        this.backend = backend;
        for (String c : new String[] {"solves", "solved", "unsat", "timeout", "solverError", "malformedInput",
                "unknownInput", "badTypeInput", "paramSent", "paramAcked", "paramRetries", "solveRetries", "droppedRules"}) {
            counters.put(c, 0L);
        }
    }

    public synchronized void count(String counter) {
        counters.merge(counter, 1L, Long::sum);
    }

    /** Sets a counter kept elsewhere (a backend's). */
    public synchronized void set(String counter, long value) {
        counters.put(counter, value);
    }

    public synchronized long get(String counter) {
        return counters.getOrDefault(counter, 0L);
    }

    /** Records a solve outcome; failures become the last error. */
    public synchronized void solveOutcome(SolveResult r) {
        count("solves");
        lastOutcome = r.status().name();
        switch (r.status()) {
            case SOLVED -> count("solved");
            case UNSAT -> count("unsat");
            case TIMEOUT -> count("timeout");
            case ERROR -> count("solverError");
        }
        if (!r.solved()) {
            error(r.status().name().toLowerCase(), r.message());
        }
    }

    public synchronized void error(String kind, String message) {
        lastErrorKind = kind;
        lastErrorMessage = message;
        lastErrorTime = System.currentTimeMillis();
    }

    /** The {@code miron.status} body; {@code applied} is the configuration currently in force. */
    public synchronized ObjectNode toJson(Map<String, Object> applied) {
        ObjectNode n = Json.object();
        n.put("time", System.currentTimeMillis());
        n.put("model", model);
        n.put("backend", backend);
        n.put("state", "SOLVED".equals(lastOutcome) ? "ok" : "STARTING".equals(lastOutcome) ? "starting" : "degraded");
        n.put("lastOutcome", lastOutcome);
        if (lastErrorKind != null) {
            ObjectNode e = n.putObject("lastError");
            e.put("kind", lastErrorKind);
            e.put("message", lastErrorMessage);
            e.put("time", lastErrorTime);
        }
        ObjectNode c = n.putObject("counters");
        counters.forEach(c::put);
        n.set("applied", Json.MAPPER.valueToTree(applied));
        return n;
    }
}
