package org.miron.lsp.server;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;

/** Min / median / worst of one measure over repeated server starts, as the start-up benchmarks print them. */
final class Spread {

    private Spread() {
    }

    /** Prints {@code measure  min / median / worst} of column {@code index} of the runs, in a column of {@code width}. */
    static void print(String measure, int width, List<double[]> runs, int index) {
        List<Double> sorted = new ArrayList<>();
        runs.forEach(run -> sorted.add(run[index]));
        Collections.sort(sorted);
        int n = sorted.size();
        double median = n % 2 == 1 ? sorted.get(n / 2) : (sorted.get(n / 2 - 1) + sorted.get(n / 2)) / 2;
        System.out.printf(Locale.ROOT, "%-" + width + "s %6.0f / %6.0f / %6.0f%n", measure, sorted.get(0), median,
                sorted.get(n - 1));
    }
}
