package org.miron.runtime.bench;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.Reader;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.miron.runtime.Endpoints;
import org.miron.runtime.broker.Broker;
import org.miron.runtime.bus.BusClient;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.roqme.ContextDecoder;
import org.miron.runtime.roqme.LiveProvider;
import org.miron.runtime.roqme.Provider;
import org.miron.runtime.roqme.Replay;
import org.miron.runtime.roqme.expr.CompiledModel;
import org.miron.runtime.roqme.expr.Compiler;
import org.miron.runtime.roqme.model.ModelReader;
import org.miron.testkit.runtime.BusProbe;
import org.miron.testkit.runtime.TestModels;

/**
 * {@code gradle :org.miron.runtime:roqmeBench [-Psamples=N]}: the RoQME provider's replay throughput
 * (context samples per second, JSON parsing and CSV output included) on the intralogistics model and
 * on a synthetic model of 100 contexts and 500 observations with time windows; a 24-hour trace at
 * 10 Hz (864 000 samples) with the heap after it; the live latency from a context published to the
 * observation it fires on the bus. Numbers only; nothing is asserted (docs/performance.md).
 */
public final class RoqmeBench {
    private RoqmeBench() {
    }

    public static void main(String[] args) throws Exception {
        java.util.logging.Logger.getLogger("").setLevel(java.util.logging.Level.WARNING);
        int samples = args.length > 0 ? Integer.parseInt(args[0]) : 1_000_000;
        CompiledModel intra = compile(resource("intralogistics.roqme.json"));
        String synJson = synthetic(100, 500);
        System.out.println("RoQME provider bench: " + Runtime.getRuntime().availableProcessors() + " cores, "
                + samples + " samples per replay run");
        for (int round = 0; round < 2; round++) { // the first round warms the JIT
            String tag = round == 0 ? " (warm-up)" : "";
            replay("intralogistics, 100 ms apart" + tag, intra, new IntraTrace(samples, 100, 1));
            replay("synthetic 100 contexts / 500 observations" + tag, compile(synJson), new SyntheticTrace(samples, 100, 10, 2));
        }
        System.gc();
        long before = usedHeap();
        Runtime rt = Runtime.getRuntime();
        long t0 = System.nanoTime();
        long c0 = cpu();
        IntraTrace day = new IntraTrace(864_000, 100, 3);
        long ticks = new Replay(intra, 1000, null, null, Replay.Format.CSV).run(day, "day", Writer.nullWriter());
        double s = (System.nanoTime() - t0) / 1e9;
        double c = (cpu() - c0) / 1e9;
        System.gc();
        System.out.printf("24 h at 10 Hz (864 000 samples, %d ticks): %.2f s wall, %.2f s CPU; heap after GC %d kB before, "
                + "%d kB after (max %d MB)%n", ticks, s, c, before / 1024, usedHeap() / 1024, rt.maxMemory() >> 20);
        core("intralogistics, provider alone (decoded samples)", intra, samples);
        live(intra);
    }

    private static long usedHeap() {
        Runtime rt = Runtime.getRuntime();
        return rt.totalMemory() - rt.freeMemory();
    }

    static String resource(String name) throws IOException {
        return TestModels.roqme(name);
    }

    static CompiledModel compile(String json) throws Exception {
        return Compiler.compile(ModelReader.parse("bench.roqme.json", json), new java.util.HashMap<>());
    }

    /** CPU time of this thread: on a shared machine it measures the work, not the wait for a core. */
    private static long cpu() {
        return java.lang.management.ManagementFactory.getThreadMXBean().getCurrentThreadCpuTime();
    }

    private static void replay(String name, CompiledModel m, BufferedReader trace) throws Exception {
        long t0 = System.nanoTime();
        long c0 = cpu();
        long ticks = new Replay(m, 1000, null, null, Replay.Format.CSV).run(trace, name, Writer.nullWriter());
        double s = (System.nanoTime() - t0) / 1e9;
        double c = (cpu() - c0) / 1e9;
        long n = ((Counted) trace).count();
        System.out.printf("replay %-44s %,10.0f samples/s wall, %,10.0f per CPU second (%d samples, %d ticks, %.2f s)%n",
                name, n / s, n / c, n, ticks, s);
    }

    /** The provider alone on decoded samples: what the JSON parsing costs, by difference. */
    private static void core(String name, CompiledModel m, int samples) throws Exception {
        ContextDecoder dec = new ContextDecoder(m);
        IntraTrace trace = new IntraTrace(samples, 100, 4);
        List<ContextDecoder.Sample> decoded = new ArrayList<>();
        String line;
        while ((line = trace.readLine()) != null) {
            decoded.add(dec.decode(line.getBytes(StandardCharsets.UTF_8)));
        }
        for (int round = 0; round < 2; round++) {
            Provider p = new Provider(m, 1000, decoded.get(0).time()).start();
            long t0 = System.nanoTime();
            long c0 = cpu();
            for (ContextDecoder.Sample smp : decoded) {
                while (p.nextTickTime() < smp.time()) {
                    p.tick();
                }
                p.input(smp.slot(), smp.value(), smp.time());
            }
            double s = (System.nanoTime() - t0) / 1e9;
            double c = (cpu() - c0) / 1e9;
            if (round == 1) {
                System.out.printf("%-51s %,10.0f samples/s wall, %,10.0f per CPU second%n", name, decoded.size() / s, decoded.size() / c);
            }
        }
    }

    /** Context published → roqme.observation received, over loopback through the broker. */
    private static void live(CompiledModel m) throws Exception {
        Endpoints ep = Endpoints.freeLoopback();
        try (Broker broker = new Broker(ep).start();
                BusProbe probe = new BusProbe(ep.busOut(), Topics.OBSERVATION);
                BusClient in = new BusClient("bench-input", ep.busIn(), null, List.of(), (t, b) -> { }).start();
                LiveProvider p = new LiveProvider(m, 1000, 5000, ep.busIn(), ep.busOut()).start()) {
            in.awaitReady(10_000);
            p.awaitReady(10_000);
            while (p.contexts() == 0) {
                in.publish(Topics.CONTEXT, battery(90));
                Thread.sleep(50);
            }
            int rounds = 400;
            long[] lat = new long[rounds];
            for (int i = 0; i < rounds; i++) {
                in.publish(Topics.CONTEXT, battery(90)); // batteryLow fires again only after the level rose
                Thread.sleep(20);
                long wall = System.currentTimeMillis(); // the observation's time is its context's arrival, later
                long t0 = System.nanoTime();
                in.publish(Topics.CONTEXT, battery(10));
                probe.await(Topics.OBSERVATION, b -> b.path("name").asText().equals("batteryLow")
                        && b.path("time").asLong() >= wall, 10_000);
                lat[i] = System.nanoTime() - t0;
            }
            Arrays.sort(lat);
            System.out.printf("live: context published -> roqme.observation received: p50 %.2f ms, p99 %.2f ms (%d rounds)%n",
                    lat[rounds / 2] / 1e6, lat[rounds * 99 / 100] / 1e6, rounds);
        }
    }

    private static String battery(double v) {
        return "{\"name\":\"BatteryLevel\",\"namespace\":\"Intralogistics\",\"type\":\"number\",\"value\":" + v + "}";
    }

    interface Counted {
        long count();
    }

    /** A trace generated line by line (never held in memory). */
    abstract static class Generated extends BufferedReader implements Counted {
        final Random rnd;
        final long n;
        final long stepMs;
        long i;

        Generated(long n, long stepMs, long seed) {
            super(Reader.nullReader());
            this.n = n;
            this.stepMs = stepMs;
            this.rnd = new Random(seed);
        }

        @Override
        public String readLine() {
            if (i >= n) {
                return null;
            }
            String l = line(1_000_000 + i * stepMs);
            i++;
            return l;
        }

        @Override
        public long count() {
            return i;
        }

        abstract String line(long time);
    }

    /** Intralogistics contexts in random walks: battery, distances, space, dock, deliveries and stops. */
    static final class IntraTrace extends Generated {
        private double battery = 60;
        private double human = 5;
        private double obstacle = 5;

        IntraTrace(long n, long stepMs, long seed) {
            super(n, stepMs, seed);
        }

        @Override
        String line(long time) {
            int k = rnd.nextInt(100);
            String body;
            if (k < 30) {
                battery = Math.max(0, Math.min(100, battery + rnd.nextGaussian() * 3));
                body = "\"name\":\"BatteryLevel\",\"type\":\"number\",\"value\":" + battery;
            } else if (k < 55) {
                human = Math.max(0, Math.min(20, human + rnd.nextGaussian() * 0.5));
                body = "\"name\":\"HumanDistance\",\"type\":\"number\",\"value\":" + human;
            } else if (k < 80) {
                obstacle = Math.max(0, Math.min(20, obstacle + rnd.nextGaussian() * 0.5));
                body = "\"name\":\"ObstacleDistance\",\"type\":\"number\",\"value\":" + obstacle;
            } else if (k < 88) {
                body = "\"name\":\"FreeSpace\",\"type\":\"enum\",\"value\":\"" + new String[] {"LOW", "MEDIUM", "HIGH"}[rnd.nextInt(3)] + "\"";
            } else if (k < 94) {
                body = "\"name\":\"Docked\",\"type\":\"boolean\",\"value\":" + rnd.nextBoolean();
            } else if (k < 99) {
                body = "\"name\":\"DeliveryDone\",\"type\":\"event\",\"value\":true";
            } else {
                body = "\"name\":\"EmergencyStop\",\"type\":\"event\",\"value\":true";
            }
            return "{" + body + ",\"namespace\":\"Intralogistics\",\"time\":" + time + "}";
        }
    }

    /** Random samples of the synthetic model's contexts c0..c(k-1). */
    static final class SyntheticTrace extends Generated {
        private final int contexts;

        SyntheticTrace(long n, long stepMs, int perMs, long seed) {
            super(n, stepMs / perMs, seed);
            this.contexts = 100;
        }

        @Override
        String line(long time) {
            return "{\"name\":\"c" + rnd.nextInt(contexts) + "\",\"type\":\"number\",\"value\":" + rnd.nextInt(100) + ",\"time\":" + time + "}";
        }
    }

    /**
     * A runtime model of {@code contexts} number contexts, 10 properties and {@code observations}
     * observations over time windows: avg/max/min/count over 10-60 s, trends over samples, comparisons.
     */
    static String synthetic(int contexts, int observations) {
        StringBuilder b = new StringBuilder("{\"format\":1,\"model\":\"synthetic\",\"source\":\"synthetic.roqme\",\"contexts\":[");
        for (int i = 0; i < contexts; i++) {
            b.append(i == 0 ? "" : ",").append("{").append(decl("c" + i, i)).append(",\"type\":{\"kind\":\"number\"}}");
        }
        b.append("],\"params\":[],\"vars\":[],\"timers\":[],\"beliefs\":[");
        for (int i = 0; i < 10; i++) {
            b.append(i == 0 ? "" : ",").append("{").append(decl("p" + i, 1000 + i)).append(",\"kind\":\"property\",\"reference\":0.5,\"survivalMs\":60000,\"expr\":null}");
        }
        b.append("],\"observations\":[");
        String[] fns = {"avg", "max", "min", "count"};
        Random rnd = new Random(5);
        for (int i = 0; i < observations; i++) {
            String c = "{\"type\":\"number\",\"ref\":\"c" + (i % contexts) + "\"}";
            String fn = fns[i % 4];
            long window = 10_000 + 10_000 * (i % 6);
            String win = "{\"type\":\"number\",\"call\":\"" + fn + "\",\"args\":[" + c + ",{\"type\":\"time\",\"time\":" + window + "}]}";
            double threshold = fn.equals("count") ? 5 + rnd.nextInt(10) : 20 + rnd.nextInt(60);
            String pattern = "{\"type\":\"boolean\",\"op\":\"" + (i % 2 == 0 ? ">" : "<") + "\",\"left\":" + win
                    + ",\"right\":{\"type\":\"number\",\"number\":" + threshold + "}}";
            if (i % 5 == 4) { // a trend over the last 5 samples, as event logic with the window
                pattern = "{\"type\":\"event\",\"op\":\"and\",\"left\":" + pattern + ",\"right\":{\"type\":\"boolean\",\"call\":\"increasing\",\"args\":["
                        + c + ",{\"type\":\"number\",\"number\":5}]}}";
            }
            b.append(i == 0 ? "" : ",").append("{").append(decl("o" + i, 2000 + i)).append(",\"pattern\":").append(pattern)
                    .append(",\"actions\":[{\"kind\":\"").append(i % 3 == 0 ? "undermines" : "reinforces")
                    .append("\",\"belief\":\"p").append(i % 10).append("\",\"strength\":\"").append(new String[] {"LOW", "MEDIUM", "HIGH"}[i % 3])
                    .append("\",\"survivalMs\":null}]}");
        }
        return b.append("]}").toString();
    }

    private static String decl(String id, int line) {
        return "\"id\":\"" + id + "\",\"name\":\"" + id + "\",\"namespace\":\"Syn\",\"at\":\"synthetic.roqme:" + line + ":1\"";
    }
}
