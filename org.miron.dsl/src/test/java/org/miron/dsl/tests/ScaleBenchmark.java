package org.miron.dsl.tests;

import java.io.File;
import java.nio.file.Files;

/**
 * Prints how long loading and validating a large MIRoN model takes (gradle :org.miron.dsl:benchmark),
 * at a few sizes, so a quadratic blow-up shows as a number rather than a flaky timed test.
 */
public final class ScaleBenchmark {
    private ScaleBenchmark() {
    }

    public static void main(String[] args) throws Exception {
        for (int n : new int[] { 250, 500, 1000, 1500 }) {
            File dir = Files.createTempDirectory("miron-scale").toFile();
            File main = ScaleTest.write(dir, n);
            long start = System.nanoTime();
            long errors = Models.validateAll(Models.load(main)).size();
            long ms = (System.nanoTime() - start) / 1_000_000;
            System.out.printf("%6d elements: loaded and validated in %6d ms (%d issues)%n", 6 * n, ms, errors);
        }
    }
}
