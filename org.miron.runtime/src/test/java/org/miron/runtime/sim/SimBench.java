package org.miron.runtime.sim;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * {@code gradle :org.miron.runtime:simBench}: how fast the simulator runs the intralogistics
 * example in its world (docs/performance.md). Prints, for one thread, the wall and CPU time of a
 * 1-, 4- and 8-hour shift per policy and the heap after each (flat in the duration: nothing is kept
 * per event unless a timeline is asked for); then N runs of 8 h on every core. Asserts nothing.
 */
public final class SimBench {
    private SimBench() {
    }

    public static void main(String[] args) throws Exception {
        int runs = args.length > 0 ? Integer.parseInt(args[0]) : 20;
        Path dir = Files.createTempDirectory("miron-simbench");
        Setup setup = SimFixture.setup("intralogistics", "intralogistics", SimFixture.intralogisticsWorld(), dir);
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        new Simulation(setup, Policy.parse("adaptive"), 99, 3_600_000L, -1).run(); // warm-up
        System.out.printf("%-22s %6s %9s %9s %12s %10s%n", "policy", "shift", "wall s", "cpu s", "x real time", "heap MiB");
        for (String policy : List.of("adaptive", "preset")) {
            for (int hours : new int[] { 1, 4, 8 }) {
                long cpu0 = threads.getCurrentThreadCpuTime();
                long t0 = System.nanoTime();
                new Simulation(setup, Policy.parse(policy), 1, hours * 3_600_000L, -1).run();
                double wall = (System.nanoTime() - t0) / 1e9;
                double cpu = (threads.getCurrentThreadCpuTime() - cpu0) / 1e9;
                System.gc();
                Runtime rt = Runtime.getRuntime();
                System.out.printf("%-22s %5dh %9.2f %9.2f %12.0f %10.1f%n", policy, hours, wall, cpu, hours * 3600 / cpu,
                        (rt.totalMemory() - rt.freeMemory()) / 1048576.0);
            }
        }
        int cores = Runtime.getRuntime().availableProcessors();
        for (int t : new int[] { 1, cores }) {
            long t0 = System.nanoTime();
            Comparison.run(setup, List.of(Policy.parse("adaptive")), runs, 1, 8 * 3_600_000L, -1, t);
            double wall = (System.nanoTime() - t0) / 1e9;
            System.out.printf("%d runs of 8 h, adaptive, %d thread(s): %.1f s wall (%.0fx real time)%n", runs, t, wall,
                    runs * 8 * 3600 / wall);
        }
        List<Path> left = new ArrayList<>();
        try (var s = Files.walk(dir)) {
            s.sorted(java.util.Comparator.reverseOrder()).forEach(left::add);
        }
        for (Path p : left) {
            Files.deleteIfExists(p);
        }
    }
}
