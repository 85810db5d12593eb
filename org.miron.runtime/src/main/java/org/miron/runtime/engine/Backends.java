package org.miron.runtime.engine;

import java.util.List;
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
            "minizinc", Backends::minizinc,
            "native", Backends::nativeBackend,
            "both", (model, o) -> new CrossCheckBackend(minizinc(model, o), nativeBackend(model, o))));

    private Backends() {
    }

    private static SolverBackend minizinc(IoModel model, EngineOptions o) {
        return new MiniZincBackend(model, o.minizinc, o.solver, o.timeLimitMs);
    }

    /** Throws IllegalArgumentException when the io.json has no usable decision section. */
    private static SolverBackend nativeBackend(IoModel model, EngineOptions o) {
        return new NativeBackend(model);
    }

    /** The names {@code --backend} accepts, sorted. */
    public static synchronized List<String> names() {
        return List.copyOf(FACTORIES.keySet());
    }

    public static synchronized void register(String name, Factory factory) {
        FACTORIES.put(name, factory);
    }

    /**
     * @param name a backend, or null for the default: {@code native} (proved equal to MiniZinc by
     *             the differential test), or {@code minizinc} for an io.json without a
     *             {@code decision} section (generated before it existed, or written by hand)
     */
    public static synchronized SolverBackend create(String name, IoModel model, EngineOptions options)
            throws EngineStartException {
        if (name == null) {
            name = model.decision() != null ? "native" : "minizinc";
        }
        Factory f = FACTORIES.get(name);
        if (f == null) {
            throw new EngineStartException("unknown backend '" + name + "' (available: "
                    + String.join(", ", names()) + ")");
        }
        try {
            return f.create(model, options);
        } catch (IllegalArgumentException e) {
            throw new EngineStartException("backend " + name + ": " + e.getMessage());
        }
    }
}
