package org.miron.runtime.bench;

import java.io.File;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;

import org.eclipse.emf.ecore.resource.Resource;
import org.miron.generator.WeightPolicy;
import org.miron.generator.standalone.BatchGeneration;
import org.miron.generator.standalone.ModelLoader;
import org.miron.runtime.engine.Backends;
import org.miron.runtime.engine.EngineOptions;
import org.miron.runtime.engine.InputState;
import org.miron.runtime.engine.IoModel;
import org.miron.runtime.engine.SolveResult;
import org.miron.runtime.engine.SolverBackend;
import org.miron.testkit.RepositoryRoot;
import org.miron.testkit.runtime.ZmqPath;

/**
 * {@code gradle :org.miron.runtime:bench [-Pbackends=minizinc,native] [-Prounds=N]}: prints, per
 * backend, decision p50/p99 and allocation per decision on intralogistics and on synthetic models
 * (SyntheticModel) of 5/50/200/1 000 varpoints, the time to generate the 1 000-varpoint model, and
 * end-to-end latencies over loopback sockets (EndToEnd), once more with repeated inputs answered
 * from a cache (the bus and engine alone), and the libzmq floor of the same path measured in the
 * same run (ZmqPath: a pyzmq relay), each end-to-end figure also as a multiple of it, with our
 * broker and engine driven by the floor's own pyzmq driver too. Numbers only; nothing is asserted.
 */
public final class Bench {
    private static final int[] SIZES = { 5, 50, 200, 1000 };

    public static void main(String[] args) throws Exception {
        // Per-decision INFO lines (acknowledged change-parameters) would flood the output and time the console.
        java.util.logging.Logger.getLogger("").setLevel(java.util.logging.Level.WARNING);
        List<String> backends = args.length > 0 && !args[0].isBlank() ? List.of(args[0].split(",")) : Backends.names();
        int rounds = args.length > 1 ? Integer.parseInt(args[1]) : 40;
        Path dir = Files.createTempDirectory("miron-bench");
        Path root = RepositoryRoot.path();
        System.out.println("MIRoN bench: backends " + backends + ", " + rounds + " rounds (fewer on large models), "
                + Runtime.getRuntime().availableProcessors() + " cores");

        Map<String, Path> models = new LinkedHashMap<>();
        models.put("intralogistics", generateExample(root.resolve("examples/intralogistics/intralogistics.miron"),
                dir.resolve("intralogistics")));
        boolean e2eOnly = "e2e".equals(System.getProperty("bench.only")); // -Ponly=e2e
        for (int n : e2eOnly ? new int[0] : SIZES) {
            long t0 = System.nanoTime();
            models.put("synthetic " + n, SyntheticModel.generate(n, dir.resolve("syn" + n)));
            if (n == 1000) {
                System.out.printf("generation of the 1 000-varpoint model (in this JVM, warm): %.1f s%n",
                        (System.nanoTime() - t0) / 1e9);
            }
        }

        System.out.println();
        System.out.println("decision (backend.solve), ms         backend       p50       p99   alloc/decision  not optimal");
        for (String backend : e2eOnly ? List.<String>of() : backends) {
            for (Map.Entry<String, Path> m : models.entrySet()) {
                IoModel io = IoModel.load(m.getValue());
                int n = io.varpoints().size();
                // In-process solves take microseconds: many more rounds, so that p99 is not the maximum.
                int r = !backend.equals("minizinc") && !backend.equals("both") ? Math.max(rounds, 2000)
                        : n >= 1000 ? Math.max(3, rounds / 8) : n >= 200 ? Math.max(5, rounds / 4) : rounds;
                decisions(backend, m.getKey(), m.getValue(), io, r);
            }
        }

        System.out.println();
        System.out.println("end to end over loopback (broker, engine, skill mock), ms   backend       p50       p99"
                + "  p50 / p99 as multiples of the libzmq floor");
        // The floor of the same path in the same run (issue 39), and our broker and engine driven by
        // the floor's own publisher and subscriber.
        ZmqPath py = ZmqPath.ensure(root);
        ZmqPath.Figures floor = py.floor(300, 1000);
        System.out.printf("%-60s %-9s %s%n", "libzmq floor: C proxy + echo, pyzmq driver (" + floor.rounds + ")", "",
                floor.measured() ? String.format("%9.3f %9.3f  (%s)", floor.p50Ms, floor.p99Ms, floor.versions)
                        : "not measured: " + floor.notMeasured);
        if (py.available()) {
            EndToEnd.pyDriven(models.get("intralogistics"), py, 300, 1000, floor, EndToEnd.Between.SOCKETS);
            // The steady state (the JIT compiles the bus path only after some thousands of messages):
            // over sockets, on the local link (miron run's), and JeroMQ's own part of the path.
            for (EndToEnd.Between b : EndToEnd.Between.values()) {
                EndToEnd.pyDriven(models.get("intralogistics"), py, 5000, 2000, floor, b);
            }
        }
        for (String backend : backends) {
            boolean fast = backend.equals("native");
            int r = fast ? Math.max(rounds, 1000) : rounds; // fast: a p99 worth the name
            int warm = fast ? 300 : 3; // the JIT's first compilations, reported apart
            EndToEnd.run(backend, models.get("intralogistics"), warm, r, false, floor);
            EndToEnd.run(backend, models.get("intralogistics"), warm, r, true, floor);
        }
    }

    private static void decisions(String backend, String label, Path ioJson, IoModel io, int rounds) {
        EngineOptions o = new EngineOptions(ioJson);
        o.backend = backend;
        o.timeLimitMs = 0; // automatic, as the engine runs by default
        Random random = new Random(42);
        long[] times = new long[rounds];
        long allocated = 0;
        int notOptimal = 0;
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        try (SolverBackend b = Backends.create(backend, io, o)) {
            Map<String, Object> base = new InputState(io).snapshot().params();
            for (int w = 0; w < Math.min(rounds, 500); w++) { // warm-up: the JIT compiles the in-process solver
                b.solve(new LinkedHashMap<>(base));
            }
            for (int i = 0; i < rounds; i++) {
                Map<String, Object> params = new LinkedHashMap<>(base);
                boolean zero = i % 3 == 0; // new metrics every round, every third all 0 (the largest objective)
                params.replaceAll((k, v) -> k.startsWith("metric_") ? (zero ? 0.0 : random.nextDouble()) : v);
                long a0 = threads.getCurrentThreadAllocatedBytes();
                long t0 = System.nanoTime();
                SolveResult res = b.solve(params);
                times[i] = System.nanoTime() - t0;
                allocated += threads.getCurrentThreadAllocatedBytes() - a0;
                if (!res.solved()) {
                    throw new IllegalStateException(label + ": " + res.status() + " " + res.message());
                }
                if (!res.optimal()) {
                    notOptimal++;
                }
            }
        } catch (Exception e) {
            System.out.printf("%-36s %-9s failed: %s%n", label, backend, e.getMessage());
            return;
        }
        System.out.printf("%-36s %-9s %s %12.3f KiB %6d/%d%n", label + " (" + rounds + " rounds)", backend,
                new Stats(times).p50p99(), allocated / 1024.0 / rounds, notOptimal, rounds);
    }

    static Path generateExample(Path miron, Path out) throws Exception {
        Files.createDirectories(out);
        ModelLoader loader = new ModelLoader();
        List<Resource> resources = new ArrayList<>(List.of(loader.load(new File(miron.toString()))));
        BatchGeneration.Outcome outcome = new BatchGeneration(loader, WeightPolicy.NEED)
                .run(resources, BatchGeneration.folder(out));
        if (!outcome.succeeded()) {
            throw new IllegalStateException("cannot generate " + miron + ": " + outcome.validation());
        }
        String name = miron.getFileName().toString().replace(".miron", "");
        return out.resolve(name + ".io.json");
    }
}
