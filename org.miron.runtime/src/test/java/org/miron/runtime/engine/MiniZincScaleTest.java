package org.miron.runtime.engine;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.bench.SyntheticModel;

/**
 * A generated 1 000-varpoint model solved by the real minizinc through the engine's backend with
 * every metric 0, the case that used to fail: the parameters are too long for one command-line
 * argument, and the old objective (3N+1) * gain passed Gecode's 32-bit integers ("invalid
 * integer literal"). The optimum is computed independently from the generated utility tables.
 */
public class MiniZincScaleTest {
    private static final int N = 1000;

    @ClassRule
    public static TemporaryFolder temp = new TemporaryFolder();

    private static IoModel io;

    @BeforeClass
    public static void generate() throws Exception {
        io = IoModel.load(SyntheticModel.generate(N, temp.newFolder("syn").toPath()));
    }

    @Test
    public void allMetricsZeroSolvesToTheComputedOptimum() throws Exception {
        Map<String, Object> params = new LinkedHashMap<>(new InputState(io).snapshot().params());
        params.replaceAll((k, v) -> k.startsWith("metric_") ? 0.0 : v);
        assertTrue("the data would not fit one argument", io.varpoints().size() == N
                && org.miron.runtime.Json.write(params).length() > 131_072);
        String dzn = Files.readString(io.dzn());
        try (MiniZincBackend backend = new MiniZincBackend(io, "minizinc", "gecode", 60_000)) {
            SolveResult r = backend.solve(params);
            assertTrue(r.status() + ": " + r.message(), r.solved());
            assertTrue("proved optimal", r.optimal());
            for (int i = 0; i < N; i++) {
                String vp = SyntheticModel.varpoint(i);
                assertEquals(vp, best(dzn, vp), (int) r.decisions().get(vp + "_var"));
            }
        }
    }

    @Test
    public void theObjectiveBoundIsStatedAndFits() throws Exception {
        String mzn = Files.readString(io.mzn());
        // 1 000 varpoints x 2 utility tables: gain at most 2e7, the product form would need 3001 * 2e7.
        assertTrue(mzn.contains("solve :: int_search("));
        assertTrue(mzn.contains("maximize miron_gain;"));
        assertTrue(mzn.contains("(3001 * 20000000)"));
    }

    /**
     * Varpoint i's optimum with every weight 1: the index with the largest round(100 * sum of
     * utilities) among the values every rule allows (all fire: at most 60), the first on ties.
     */
    private static int best(String dzn, String vp) {
        List<double[]> tables = new ArrayList<>();
        Matcher m = Pattern.compile("\\b" + vp + "_y_p\\d = array1d\\(0\\.\\.99, \\[([^\\]]*)\\]\\);").matcher(dzn);
        while (m.find()) {
            String[] cells = m.group(1).trim().split("\\s*,\\s*");
            double[] t = new double[cells.length];
            for (int j = 0; j < t.length; j++) {
                t[j] = Double.parseDouble(cells[j]);
            }
            tables.add(t);
        }
        assertEquals(vp + " tables", 2, tables.size());
        int best = -1;
        long bestGain = Long.MIN_VALUE;
        for (int j = 0; j <= 60; j++) {
            double sum = 0;
            for (double[] t : tables) {
                sum += t[j];
            }
            long gain = Math.round(100.0 * sum);
            if (gain > bestGain) {
                bestGain = gain;
                best = j;
            }
        }
        return best;
    }
}
