package org.miron.runtime.bench;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;

import org.miron.runtime.Endpoints;
import org.miron.runtime.Json;
import org.miron.runtime.broker.Broker;
import org.miron.runtime.bus.BusClient;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.engine.Backends;
import org.miron.runtime.engine.Engine;
import org.miron.runtime.engine.EngineOptions;
import org.miron.runtime.engine.IoModel;
import org.miron.runtime.engine.SolveResult;
import org.miron.runtime.engine.SolverBackend;
import org.miron.runtime.skill.ParameterChange;
import org.miron.runtime.skill.SkillInterfaceMock;
import org.miron.runtime.skill.SkillTable;
import org.miron.testkit.runtime.ZmqPath;

/**
 * Input → variant and input → change-parameter on intralogistics, every component in this JVM but
 * talking over loopback TCP as separate processes would: a published estimate until the variant
 * reaches a bus subscriber, or the parameter change reaches the skill interface mock. The solver's
 * own time inside the engine is measured too (a timing wrapper around the backend), so the
 * overhead of everything else is the difference.
 */
final class EndToEnd {
    private static final long TIMEOUT_MS = 30_000;

    private EndToEnd() {
    }

    /**
     * @param warm   rounds run first and reported apart: until the JIT has compiled the bus, broker
     *               and engine paths, a round costs several times the steady state's
     * @param cached answer repeated inputs from a cache instead of the solver: what is left is the
     *               time of the bus, broker and engine alone
     */
    static void run(String backend, Path ioJson, int warm, int rounds, boolean cached, ZmqPath.Figures floor) throws Exception {
        Endpoints ep = Endpoints.freeLoopback();
        IoModel io = IoModel.load(ioJson);
        EngineOptions o = new EngineOptions(ioJson).endpoints(ep);
        o.backend = backend;
        o.timeLimitMs = 0;
        BlockingQueue<String[]> variants = new LinkedBlockingQueue<>();
        long[] solveNanos = new long[4 * (warm + rounds) + 16];
        long[] solveStart = new long[solveNanos.length]; // System.nanoTime() at each solve's start and end
        long[] solveEnd = new long[solveNanos.length];
        int[] solves = { 0 };
        try (Broker broker = new Broker(ep).start();
                SkillInterfaceMock skills = new SkillInterfaceMock(ep.skill(), ep.skillEvents(), SkillTable.defaults()).start();
                BusClient input = new BusClient("bench-input", ep.busIn(), null, List.of(), (t, b) -> { }).start();
                BusClient watch = new BusClient("bench-watch", ep.busIn(), ep.busOut(), List.of(Topics.VARIANT_PREFIX),
                        (t, b) -> variants.add(new String[] { t, new String(b, StandardCharsets.UTF_8),
                                Long.toString(System.nanoTime()) })).start();
                Engine engine = new Engine(io, timed(Backends.create(backend, io, o), solveNanos, solveStart, solveEnd, solves, cached), o)
                        .start()) {
            input.awaitReady(TIMEOUT_MS);
            watch.awaitReady(TIMEOUT_MS);
            take(variants, "task"); // the initial decision
            Thread.sleep(1000); // every subscription is live
            variants.clear();

            long[] cold = new long[warm];
            long[] variant = new long[rounds];
            long[] variantOverhead = new long[rounds];
            long[] inbound = new long[rounds]; // input published → its solve starts
            long[] outbound = new long[rounds]; // the last solve of the round ends → variant received
            for (int k = -warm; k < rounds; k++) {
                int i = k + warm; // the input alternates over all rounds, warm-up included
                int first = solves[0];
                String expect = i % 2 == 0 ? "dock" : "pickDeliverCharge";
                pause();
                long t0 = System.nanoTime();
                estimate(input, "power_autonomy", i % 2 == 0 ? 0.2 : 0.9);
                String[] got = take(variants, "task");
                if (!got[1].contains("\"" + expect + "\"")) {
                    throw new IllegalStateException("unexpected variant " + got[1]);
                }
                long received = Long.parseLong(got[2]);
                if (k < 0) {
                    cold[i] = received - t0;
                    continue;
                }
                i = k;
                variant[i] = received - t0;
                variantOverhead[i] = variant[i] - solveTime(solveNanos, first, solves[0]);
                synchronized (solveNanos) {
                    int last = Math.min(solves[0], solveNanos.length) - 1;
                    inbound[i] = first < solveNanos.length ? solveStart[first] - t0 : 0;
                    outbound[i] = last >= first ? received - solveEnd[last] : 0;
                }
            }
            int solvesBefore = solves[0];
            long[] param = new long[rounds];
            long[] paramOverhead = new long[rounds];
            for (int k = -warm; k < rounds; k++) {
                int i = k + warm;
                int first = solves[0];
                // The newest query id so far; the wait tests each change once (a predicate copying the
                // history on every test made this path quadratic: ≈ 4 ms of the bench's own).
                long lastId = skills.history().stream().mapToLong(ParameterChange::id).max().orElse(-1);
                pause();
                long t0 = System.nanoTime();
                estimate(input, "safety", i % 2 == 0 ? 0.35 : 0.95);
                ParameterChange c = skills.awaitChange(x -> x.id() > lastId, TIMEOUT_MS)
                        .orElseThrow(() -> new IllegalStateException("no change-parameter"));
                if (k < 0) {
                    continue;
                }
                i = k;
                param[i] = System.nanoTime() - t0;
                paramOverhead[i] = param[i] - solveTime(solveNanos, first, solves[0]);
                if (c == null) {
                    throw new IllegalStateException();
                }
            }
            if (Boolean.getBoolean("bench.slow")) { // -Pslow: which rounds were slow, who used the CPU
                slowRounds("variant", variant);
                slowRounds("change-parameter", param);
                threadCpu();
            }
            long[] solver = java.util.Arrays.copyOf(solveNanos, Math.min(solves[0], solveNanos.length));
            if (cached) {
                backend += " (cached)";
            }
            System.out.printf("%-60s %-9s %s%n", "input -> variant, warm-up rounds first (" + warm + ")", backend,
                    new Stats(cold).p50p99());
            Stats v = new Stats(variant);
            System.out.printf("%-60s %-9s %s  %s%n", "input -> variant (" + rounds + ")", backend, v.p50p99(),
                    floor.ratios(v.percentileMs(50), v.percentileMs(99)));
            System.out.printf("%-60s %-9s %s%n", "input -> change-parameter (" + rounds + ")", backend, new Stats(param).p50p99());
            System.out.printf("%-60s %-9s %s%n", "  overhead: input -> variant minus that round's solve", backend,
                    new Stats(variantOverhead).p50p99());
            System.out.printf("%-60s %-9s %s%n", "    inbound: input published -> solve starts", backend,
                    new Stats(inbound).p50p99());
            System.out.printf("%-60s %-9s %s%n", "    outbound: solve ends -> variant received", backend,
                    new Stats(outbound).p50p99());
            System.out.printf("%-60s %-9s %s%n", "  overhead: input -> change-parameter minus that round's solve",
                    backend, new Stats(paramOverhead).p50p99());
            System.out.printf("%-60s %-9s %s%n", "  of which solver (backend.solve in the engine, " + solver.length + ")",
                    backend, new Stats(solver).p50p99());
            if (solves[0] - solvesBefore < rounds) {
                System.out.println("  (note: fewer solves than inputs in the parameter run: " + (solves[0] - solvesBefore) + ")");
            }
        }
    }

    /** What stands between zmq_path.py's pyzmq publisher and subscriber in {@link #pyDriven}. */
    enum Between {
        /** broker and engine in this JVM over loopback sockets, as separate processes talk */
        SOCKETS("broker + engine over sockets"),
        /** the engine on the broker's local link, as in miron run */
        LOCAL("broker + engine on its local link"),
        /** the broker alone, a quick handler on its local link answering each estimate: JeroMQ's part */
        ECHO("broker + in-process echo (JeroMQ alone)");

        final String label;

        Between(String label) {
            this.label = label;
        }
    }

    /**
     * The broker (with, in this JVM, the engine and skill mock, or an echo) driven from outside by
     * zmq_path.py's pyzmq publisher and subscriber: the publisher and subscriber of the libzmq floor,
     * so that the two differ only in what stands between them.
     */
    static void pyDriven(Path ioJson, ZmqPath py, int warm, int rounds, ZmqPath.Figures floor, Between between) throws Exception {
        Endpoints ep = Endpoints.freeLoopback();
        EngineOptions o = new EngineOptions(ioJson).endpoints(ep);
        o.backend = "native";
        try (Broker broker = new Broker(ep).start();
                SkillInterfaceMock skills = new SkillInterfaceMock(ep.skill(), ep.skillEvents(), SkillTable.defaults()).start();
                AutoCloseable middle = middle(broker, o, between)) {
            ZmqPath.Figures f = py.drive(ep.busIn(), ep.busOut(), warm, rounds);
            String label = "input -> variant, pyzmq driver, " + between.label + " (" + rounds + ", " + warm + " warm-up)";
            if (!f.measured()) {
                System.out.printf("%-60s %-9s not measured: %s%n", label, "native", f.notMeasured);
                return;
            }
            System.out.printf("%-60s %-9s %9.3f %9.3f  %s%n", label, "native", f.p50Ms, f.p99Ms, floor.ratios(f.p50Ms, f.p99Ms));
        }
    }

    private static AutoCloseable middle(Broker broker, EngineOptions o, Between between) throws Exception {
        if (between == Between.ECHO) {
            org.miron.runtime.bus.Bus[] echo = new org.miron.runtime.bus.Bus[1];
            echo[0] = broker.local().open("echo", List.of(Topics.ESTIMATE), (org.miron.runtime.bus.Bus.QuickHandler) (t, b) -> {
                boolean low = new String(b, StandardCharsets.UTF_8).contains("0.2"); // the driver's two values: 0.2, 0.9
                echo[0].publish(Topics.VARIANT_PREFIX + "task", "{\"varpoint\":\"task\",\"value\":\""
                        + (low ? "dock" : "pickDeliverCharge") + "\",\"seq\":0,\"time\":" + System.currentTimeMillis() + "}");
            }).start();
            return echo[0];
        }
        if (between == Between.LOCAL) {
            o.bus = broker.local();
        }
        return Engine.create(o).start();
    }

    /** How many rounds took over 1, 2, 4 and 8 ms: a tail of whole scheduler ticks (4 ms) shows up here. */
    private static void slowRounds(String path, long[] nanos) {
        int[] over = new int[4];
        for (long n : nanos) {
            for (int b = 0; b < over.length; b++) {
                if (n > (1_000_000L << b)) {
                    over[b]++;
                }
            }
        }
        System.out.printf("  %s rounds over 1 / 2 / 4 / 8 ms: %d / %d / %d / %d of %d%n", path, over[0], over[1], over[2],
                over[3], nanos.length);
    }

    /** CPU time of every live thread of the bench's JVM (the components' bus and JeroMQ I/O threads). */
    private static void threadCpu() {
        java.lang.management.ThreadMXBean tm = java.lang.management.ManagementFactory.getThreadMXBean();
        for (long id : tm.getAllThreadIds()) {
            java.lang.management.ThreadInfo ti = tm.getThreadInfo(id);
            long cpu = tm.getThreadCpuTime(id);
            if (ti != null && cpu > 1_000_000) {
                System.out.printf("  thread %-30s cpu %8.1f ms%n", ti.getThreadName(), cpu / 1e6);
            }
        }
    }

    /** -Pgap=MS: an idle pause before each input, as inputs spaced in time would leave (default none). */
    private static void pause() throws InterruptedException {
        long gap = Long.getLong("bench.gap", 0);
        if (gap > 0) {
            Thread.sleep(gap);
        }
    }

    /** Total time of the solves numbered [from, to) (the ones a round caused). */
    private static long solveTime(long[] nanos, int from, int to) {
        long sum = 0;
        synchronized (nanos) {
            for (int i = from; i < Math.min(to, nanos.length); i++) {
                sum += nanos[i];
            }
        }
        return sum;
    }

    private static void estimate(BusClient input, String name, double value) {
        input.publish(Topics.ESTIMATE, Json.write(Map.of("name", name, "namespace", "Intralogistics", "value", value,
                "time", System.currentTimeMillis())));
    }

    private static String[] take(BlockingQueue<String[]> q, String vp) throws InterruptedException {
        long end = System.currentTimeMillis() + TIMEOUT_MS;
        while (System.currentTimeMillis() < end) {
            String[] m = q.poll(end - System.currentTimeMillis(), TimeUnit.MILLISECONDS);
            if (m != null && m[0].equals(Topics.VARIANT_PREFIX + vp)) {
                return m;
            }
        }
        throw new IllegalStateException("no variant for " + vp);
    }

    /** The backend, recording how long each solve takes. */
    private static SolverBackend timed(SolverBackend b, long[] nanos, long[] starts, long[] ends, int[] count,
            boolean cached) {
        Map<Map<String, Object>, SolveResult> cache = new java.util.HashMap<>();
        return new SolverBackend() {
            @Override
            public String name() {
                return b.name();
            }

            @Override
            public void check() throws org.miron.runtime.engine.BackendUnavailableException {
                b.check();
            }

            @Override
            public SolveResult solve(Map<String, Object> params) {
                long t0 = System.nanoTime();
                SolveResult r = cached ? cache.get(params) : null;
                if (r == null) {
                    r = b.solve(params);
                    if (cached) {
                        cache.put(new java.util.HashMap<>(params), r);
                    }
                }
                long t1 = System.nanoTime();
                synchronized (nanos) {
                    if (count[0] < nanos.length) {
                        nanos[count[0]] = t1 - t0;
                        starts[count[0]] = t0;
                        ends[count[0]] = t1;
                    }
                    count[0]++;
                }
                return r;
            }

            @Override
            public void close() {
                b.close();
            }
        };
    }
}
