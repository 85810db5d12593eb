package org.miron.tests.differential;

import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Random;
import org.miron.runtime.engine.InputSpec;
import org.miron.runtime.engine.IoModel;
import org.miron.runtime.engine.VariationPoint;

/**
 * Random engine inputs for a model: metrics (often on the 0.1 grid the rules compare with, to hit
 * the boundaries, sometimes tiny), contexts known or unknown (sometimes tiny or huge numbers: Java
 * prints them with an exponent, the parameter file must not), overrides, current values.
 */
final class RandomInputs {
    private RandomInputs() {
    }

    static Map<String, Object> generate(IoModel io, Random random) {
        Map<String, Object> params = new LinkedHashMap<>();
        for (InputSpec in : io.inputs()) {
            if (in.isMetric()) {
                int pick = random.nextInt(10); // on the 0.1 grid, anywhere, or tiny (printed 1.2E-7 by Java)
                params.put(in.param(), pick < 5 ? random.nextInt(11) / 10.0 : pick < 9 ? random.nextDouble()
                        : random.nextDouble() * 1e-6);
                continue;
            }
            boolean known = random.nextInt(4) > 0;
            params.put(in.known(), known);
            Object value = switch (in.type()) {
                case "bool" -> known && random.nextBoolean();
                case "int" -> known ? random.nextInt(in.literals().size()) : 0;
                default -> !known ? 0.0 : switch (random.nextInt(10)) {
                    case 0 -> (random.nextDouble() - 0.5) * 1e-6; // tiny
                    case 1 -> (random.nextDouble() - 0.5) * 1e12; // huge
                    default -> random.nextBoolean() ? random.nextInt(41) / 4.0 - 5 : random.nextDouble() * 15 - 5;
                };
            };
            params.put(in.param(), value);
        }
        for (VariationPoint vp : io.varpoints()) {
            int n = vp.values().size();
            boolean pinned = random.nextInt(6) == 0;
            params.put(vp.input(), pinned);
            params.put(vp.inputValue(), pinned ? random.nextInt(n) : 0);
            params.put(vp.current(), random.nextInt(3) == 0 ? -1 : random.nextInt(n));
        }
        return params;
    }
}
