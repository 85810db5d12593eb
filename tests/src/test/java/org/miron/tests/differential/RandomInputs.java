package org.miron.tests.differential;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Random;
import org.miron.runtime.engine.InputSpec;
import org.miron.runtime.engine.IoModel;
import org.miron.runtime.engine.VarPoint;

/**
 * Random engine inputs for a model: metrics (often on the 0.1 grid the rules compare with, to hit
 * the boundaries), contexts known or unknown, overrides, current values.
 */
final class RandomInputs {
    private RandomInputs() {
    }

    /**
     * Below 1e-3 Java writes doubles as 1.2E-4, which MiniZinc's --cmdline-json-data parser refuses
     * ("unexpected token `E'"): a MiniZincBackend limitation (its parameter passing is being
     * replaced by a data file), not a difference between the backends, so such values are avoided.
     */
    private static double plain(double x) {
        return Math.abs(x) < 1e-3 ? 0 : x;
    }

    static Map<String, Object> generate(IoModel io, Random random) {
        Map<String, Object> params = new LinkedHashMap<>();
        for (InputSpec in : io.inputs()) {
            if (in.isMetric()) {
                params.put(in.param(), random.nextBoolean() ? random.nextInt(11) / 10.0 : plain(random.nextDouble()));
                continue;
            }
            boolean known = random.nextInt(4) > 0;
            params.put(in.known(), known);
            Object value = switch (in.type()) {
                case "bool" -> known && random.nextBoolean();
                case "int" -> known ? random.nextInt(in.literals().size()) : 0;
                default -> known ? (random.nextBoolean() ? random.nextInt(41) / 4.0 - 5 : plain(random.nextDouble() * 15 - 5))
                        : 0.0;
            };
            params.put(in.param(), value);
        }
        for (VarPoint vp : io.varpoints()) {
            int n = vp.values().size();
            boolean pinned = random.nextInt(6) == 0;
            params.put(vp.input(), pinned);
            params.put(vp.inputValue(), pinned ? random.nextInt(n) : 0);
            params.put(vp.current(), random.nextInt(3) == 0 ? -1 : random.nextInt(n));
        }
        return params;
    }
}
