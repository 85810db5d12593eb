package org.miron.runtime.engine;

import java.util.Map;
import java.util.TreeMap;

/**
 * Solver backends by name, for {@code engine --backend NAME}. A new backend (e.g. the in-process
 * one) is one more entry here; the engine only sees {@link SolverBackend}.
 */
public final class Backends {
    /** Builds a backend for a loaded model with the engine's options. */
    public interface Factory {
        SolverBackend create(IoModel model, EngineOptions options);
    }

    private static final Map<String, Factory> FACTORIES = new TreeMap<>(Map.of(
            "minizinc", (model, o) -> new MiniZincBackend(model, o.minizinc, o.solver, o.timeLimitMs)));

    private Backends() {
    }

    public static synchronized void register(String name, Factory factory) {
        FACTORIES.put(name, factory);
    }

    public static synchronized SolverBackend create(String name, IoModel model, EngineOptions options)
            throws EngineStartException {
        Factory f = FACTORIES.get(name);
        if (f == null) {
            throw new EngineStartException("unknown backend '" + name + "' (available: "
                    + String.join(", ", FACTORIES.keySet()) + ")");
        }
        return f.create(model, options);
    }
}
