package org.miron.runtime.engine;

import java.util.List;

/**
 * One engine input from {@code name.io.json}: a RoQME metric (property estimate) or context.
 *
 * @param kind      {@code metric} or {@code context}
 * @param roqmeType context type: number, boolean, enum, event (null for metrics)
 * @param literals  enum literals (empty otherwise)
 * @param param     MiniZinc parameter holding the value
 * @param type      MiniZinc type of {@code param}: float, bool or int
 * @param known     MiniZinc bool parameter telling whether a context has a value (null for metrics)
 * @param initial   metric start value (the RoQME reference)
 */
public record InputSpec(String kind, String namespace, String name, String roqmeType, List<String> literals,
        String param, String type, String known, double initial) {

    public boolean isMetric() {
        return "metric".equals(kind);
    }

    /** The value fed while a context is still unknown. */
    public Object neutral() {
        switch (type) {
            case "bool":
                return Boolean.FALSE;
            case "int":
                return 0;
            default:
                return 0.0;
        }
    }
}
