package org.miron.runtime.engine;

import com.fasterxml.jackson.core.JsonGenerator;
import java.io.IOException;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.math.BigDecimal;
import java.util.Map;
import org.miron.runtime.Json;

/**
 * The engine's parameters as a MiniZinc JSON data file ({@code -d params.json}). MiniZinc 2.6's
 * JSON reader refuses exponents ({@code 1.2E-4}: "unexpected token `E'"), which is how Java
 * prints doubles below 1e-3 and from 1e7, and reads an integer literal given for a float
 * parameter as an int clamped to 2147483647 ({@code 10000000000} becomes 2147483647.0). So every
 * double is written as a plain decimal with a point, digit for digit the value Java holds.
 */
final class MiniZincData {
    private MiniZincData() {
    }

    /** @throws IllegalArgumentException for a non-finite double or a value of another type */
    static String json(Map<String, Object> params) {
        StringWriter out = new StringWriter(32 * params.size() + 2);
        try (JsonGenerator g = Json.MAPPER.getFactory().createGenerator(out)) {
            g.writeStartObject();
            for (Map.Entry<String, Object> e : params.entrySet()) {
                g.writeFieldName(e.getKey());
                Object v = e.getValue();
                if (v instanceof Boolean b) {
                    g.writeBoolean(b);
                } else if (v instanceof Integer || v instanceof Long) {
                    g.writeNumber(((Number) v).longValue());
                } else if (v instanceof Double || v instanceof Float) {
                    g.writeNumber(decimal(((Number) v).doubleValue(), e.getKey()));
                } else {
                    throw new IllegalArgumentException("parameter " + e.getKey() + " = " + v
                            + ": neither a boolean, an integer nor a double");
                }
            }
            g.writeEndObject();
        } catch (IOException e) {
            throw new UncheckedIOException(e); // a StringWriter does not fail
        }
        return out.toString();
    }

    /** Plain decimal text of a double, always with a point: 0.00012, 10000000000.0, -3.5. */
    static String decimal(double value, String name) {
        if (!Double.isFinite(value)) {
            throw new IllegalArgumentException("parameter " + name + " = " + value + ": not a finite number");
        }
        BigDecimal exact = new BigDecimal(Double.toString(value)); // the shortest text that reads back as value
        return (exact.scale() > 0 ? exact : exact.setScale(1)).toPlainString();
    }
}
