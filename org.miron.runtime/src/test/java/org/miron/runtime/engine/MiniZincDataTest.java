package org.miron.runtime.engine;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * Doubles of every magnitude reach the real minizinc unchanged through the parameter file: each
 * parameter is compared, inside MiniZinc, with the same double written as a .mzn literal (whose
 * lexer takes exponents). Java prints most of these with an exponent, which MiniZinc's JSON reader
 * refuses, and 1e10 as an integer, which it would clamp to 2147483647.
 */
public class MiniZincDataTest {
    private static final double[] VALUES = {1.2e-4, -3.5e-7, 1e-11, Double.MIN_VALUE, 1e10, 1.7976931348623157e308,
            -2.5e15, 12345678.9, 0.1, 1.0 / 3, -0.0, 0.0, 5.0, 0.49510210195845616};

    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    @Test
    public void tinyAndHugeDoublesReadBackExactly() throws Exception {
        Map<String, Object> params = new LinkedHashMap<>();
        StringBuilder mzn = new StringBuilder();
        StringBuilder same = new StringBuilder();
        for (int i = 0; i < VALUES.length; i++) {
            params.put("a" + i, VALUES[i]);
            mzn.append("float: a").append(i).append(";\n");
            same.append(i == 0 ? "" : " ++ \" \" ++ ").append("show(a").append(i).append(" = ").append(VALUES[i])
                    .append(')');
        }
        params.put("n", 7);
        params.put("b", true);
        mzn.append("int: n;\nbool: b;\noutput [").append(same).append(", \" \\(n) \\(b)\"];\n");
        Path model = temp.getRoot().toPath().resolve("t.mzn");
        Path data = temp.getRoot().toPath().resolve("params.json");
        Files.writeString(model, mzn);
        Files.writeString(data, MiniZincData.json(params));
        Process p = new ProcessBuilder("minizinc", "--solver", "gecode", model.toString(), data.toString())
                .redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        assertEquals(out, 0, p.exitValue());
        String expected = "true ".repeat(VALUES.length) + "7 true";
        assertTrue(out, out.contains(expected));
    }

    @Test
    public void aNonFiniteValueIsAClearError() {
        try {
            MiniZincData.json(Map.of("metric_p", Double.NaN));
        } catch (IllegalArgumentException e) {
            assertEquals("parameter metric_p = NaN: not a finite number", e.getMessage());
            return;
        }
        throw new AssertionError("NaN accepted");
    }
}
