package org.miron.runtime.sim;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import org.miron.runtime.requirement.RequirementModel;
import org.miron.runtime.requirement.RequirementMonitors;
import org.miron.runtime.requirement.RequirementResult;

/**
 * {@code gradle :org.miron.runtime:requirementBench [-Pruns=N]}: what the requirement monitors cost
 * (docs/performance.md). An 8-hour shift of the intralogistics example on one thread, with and
 * without its requirements (as miron generate writes them), N times each, alternating: the median
 * CPU time of each and the overhead; then the monitors alone on a 24-hour stream of a change every
 * 100 ms, printing what they remember at most (bounded by the largest window, not the run's
 * length). Asserts nothing.
 */
public final class RequirementBench {
    private RequirementBench() {
    }

    public static void main(String[] args) throws Exception {
        int runs = args.length > 0 ? Integer.parseInt(args[0]) : 7;
        Path dir = Files.createTempDirectory("miron-reqbench");
        Setup plain = SimFixture.setup("intralogistics", "intralogistics", SimFixture.intralogisticsWorld(), dir);
        RequirementModel model = RequirementModel.load(dir.resolve("intralogistics.requirements.json"));
        Setup checked = new Setup(plain.io(), plain.roqme(), plain.tree(), plain.world(), model);
        ThreadMXBean threads = ManagementFactory.getThreadMXBean();
        for (int i = 0; i < 2; i++) { // warm-up
            new Simulation(plain, Policy.parse("adaptive"), 99, 3_600_000L, -1).run();
            new Simulation(checked, Policy.parse("adaptive"), 99, 3_600_000L, -1).run();
        }
        double[] without = new double[runs];
        double[] with = new double[runs];
        for (int i = 0; i < runs; i++) {
            without[i] = cpu(threads, plain, i);
            with[i] = cpu(threads, checked, i);
        }
        java.util.Arrays.sort(without);
        java.util.Arrays.sort(with);
        double a = without[runs / 2];
        double b = with[runs / 2];
        System.out.printf("8-hour shift, adaptive, one thread, median of %d: %.3f s CPU without requirements, %.3f s with %d "
                + "(%+.1f %%)%n", runs, a, b, model.requirements().size(), 100 * (b - a) / a);
        // the monitors alone: a day of changes every 100 ms
        RequirementMonitors m = new RequirementMonitors(model);
        int most = 0;
        long t0 = threads.getCurrentThreadCpuTime();
        long day = 24 * 3_600_000L;
        for (long t = 0; t < day; t += 100) {
            long k = t / 100;
            m.context(t, "BatteryLevel", (double) (k % 100));
            m.context(t, "HumanDistance", (k % 37) / 10.0);
            m.context(t, "Docked", k % 53 < 5);
            m.estimate(t, "power_autonomy", (k % 97) / 100.0);
            most = Math.max(most, m.remembered());
        }
        java.util.List<RequirementResult> r = m.finish(day);
        double cpu = (threads.getCurrentThreadCpuTime() - t0) / 1e9;
        System.gc();
        Runtime rt = Runtime.getRuntime();
        System.out.printf("monitors alone, 24 h at 10 Hz (864 000 instants): %.2f s CPU, %.2f µs an instant, at most %d "
                + "instants remembered, %d violations, heap after %.1f MiB%n", cpu, cpu * 1e6 / 864_000, most,
                r.stream().mapToInt(RequirementResult::violations).sum(), (rt.totalMemory() - rt.freeMemory()) / 1048576.0);
    }

    private static double cpu(ThreadMXBean threads, Setup setup, int seed) {
        long cpu0 = threads.getCurrentThreadCpuTime();
        new Simulation(setup, Policy.parse("adaptive"), 1 + seed, 8 * 3_600_000L, -1).run();
        return (threads.getCurrentThreadCpuTime() - cpu0) / 1e9;
    }
}
