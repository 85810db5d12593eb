package org.miron.runtime.engine;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import java.util.concurrent.atomic.AtomicLong;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.miron.runtime.Json;
import org.miron.runtime.bus.BusClient;
import org.miron.runtime.bus.Topics;
import org.miron.testkit.runtime.EngineFixture;

/**
 * Soak run of the engine on a live bus ({@code gradle :org.miron.runtime:soak -Pminutes=N}): broker,
 * engine (real minizinc) and skill mock on loopback, fed a fast random stream of estimates and
 * contexts with malformed, unknown and mistyped messages mixed in. It checks what "runs for hours"
 * means: no decision lost on the bus (consecutive seq), the decision log complete, bad input
 * counted, the engine alive, the last inputs decided and applied, and prints throughput and heap.
 * A benchmark, not a unit test: nothing here is timed against a target. With a second argument
 * {@code faults} it runs {@link FaultSoak} instead.
 */
public final class EngineSoak {
    private EngineSoak() {
    }

    public static void main(String[] args) throws Exception {
        double minutes = args.length > 0 ? Double.parseDouble(args[0]) : 1.0;
        if (args.length > 1 && args[1].equals("faults")) {
            boolean ok = FaultSoak.run(minutes);
            System.out.println(ok ? "soak faults: OK" : "soak faults: FAILED");
            System.exit(ok ? 0 : 1);
        }
        Logger.getLogger("").setLevel(Level.SEVERE); // bad input is logged per message: thousands of lines
        Path dir = Files.createTempDirectory("miron-soak");
        Random random = new Random(42);
        AtomicLong lastSeq = new AtomicLong();
        AtomicLong gaps = new AtomicLong();
        AtomicLong decisions = new AtomicLong();
        java.util.concurrent.atomic.AtomicReference<JsonNode> last = new java.util.concurrent.atomic.AtomicReference<>();
        long sentBad = 0;
        long sentGood = 0;
        try (EngineFixture f = new EngineFixture(dir)) {
            f.startAll();
            // The fixture's probe records every message: a soak must measure the engine, not it.
            f.probe.close();
            long heapStart = usedHeapAfterGc();
            try (BusClient watcher = new BusClient("soak-watch", f.endpoints.busIn(), f.endpoints.busOut(),
                    List.of(Topics.DECISION), (topic, body) -> {
                        JsonNode decision = read(body);
                        last.set(decision);
                        long seq = decision == null ? -1 : decision.path("seq").asLong();
                        long previous = lastSeq.getAndSet(seq);
                        if (previous != 0 && seq != previous + 1 && seq != previous) {
                            gaps.incrementAndGet(); // seq == previous: the cache's replay of the current one
                        }
                        decisions.incrementAndGet();
                    }).start()) {
                long end = System.currentTimeMillis() + (long) (minutes * 60_000);
                long start = System.currentTimeMillis();
                long heapMax = heapStart;
                while (System.currentTimeMillis() < end) {
                    int kind = random.nextInt(100);
                    if (kind < 45) {
                        f.estimate(random.nextBoolean() ? "power_autonomy" : "safety", Math.round(random.nextDouble() * 100) / 100.0);
                        sentGood++;
                    } else if (kind < 94) {
                        f.publish(Topics.CONTEXT, "{\"name\":\"BatteryLevel\",\"namespace\":\"Intralogistics\",\"type\":\"number\",\"value\":"
                                + random.nextInt(101) + "}");
                        sentGood++;
                    } else if (kind < 96) {
                        f.publish(Topics.ESTIMATE, "{not json");
                        sentBad++;
                    } else if (kind < 98) {
                        f.publish(Topics.ESTIMATE, "{\"name\":\"no_such_metric\",\"value\":0.5}");
                        sentBad++;
                    } else {
                        f.publish(Topics.CONTEXT, "{\"name\":\"BatteryLevel\",\"namespace\":\"Intralogistics\",\"type\":\"boolean\",\"value\":true}");
                        sentBad++;
                    }
                    Thread.sleep(2);
                    if ((sentGood + sentBad) % 5000 == 0) {
                        heapMax = Math.max(heapMax, usedHeapAfterGc());
                    }
                }
                long seconds = Math.max(1, (System.currentTimeMillis() - start) / 1000);
                // The last word: battery critical, safety low. The engine must decide and apply it.
                f.estimate("power_autonomy", 0.1);
                f.estimate("safety", 0.2);
                boolean dock = lastDecisionBecomes(last, "task", "dock") && lastDecisionBecomes(last, "maxVelocity", "28");
                boolean transvel = lastChangeBecomes(f, 28.0);
                long logLines = Files.readAllLines(dir.resolve("decisions.jsonl")).size();
                var status = f.engine.status();
                System.out.printf("soak: %d s, %d inputs (%.0f/s) and %d bad messages published%n", seconds,
                        sentGood, (double) sentGood / seconds, sentBad);
                System.out.printf("soak: %d solves, %d decisions on the bus (%.1f/s), last seq %d, seq gaps %d%n",
                        status.get("solves"), decisions.get(), (double) decisions.get() / seconds, lastSeq.get(), gaps.get());
                System.out.printf("soak: bad input counted: malformed %d, unknown %d, bad type %d (published %d)%n",
                        status.get("malformedInput"), status.get("unknownInput"), status.get("badTypeInput"), sentBad);
                System.out.printf("soak: decision log %d lines; engine alive %b; last inputs -> task dock %b, transvel 28 %b%n",
                        logLines, f.engine.isAlive(), dock, transvel);
                System.out.printf("soak: heap after GC %d MiB at start, %d MiB at most%n", heapStart >> 20, heapMax >> 20);
                long counted = status.get("malformedInput") + status.get("unknownInput") + status.get("badTypeInput");
                boolean ok = gaps.get() == 0 && f.engine.isAlive() && dock && transvel && counted == sentBad
                        && logLines >= lastSeq.get();
                System.out.println(ok ? "soak: OK" : "soak: FAILED");
                if (!ok) {
                    System.exit(1);
                }
            }
        }
    }

    /** Whether the skill interface's last applied change-parameter reaches {@code value} in time. */
    private static boolean lastChangeBecomes(EngineFixture f, double value) throws InterruptedException {
        long end = System.currentTimeMillis() + EngineFixture.TIMEOUT;
        while (System.currentTimeMillis() < end) {
            var history = f.skills.history();
            if (!history.isEmpty() && history.get(history.size() - 1).value() == value) {
                return true;
            }
            Thread.sleep(20);
        }
        return false;
    }

    /** Whether the latest decision on the bus gets {@code varpoint} = {@code value} in time. */
    private static boolean lastDecisionBecomes(java.util.concurrent.atomic.AtomicReference<JsonNode> last,
            String varpoint, String value) throws InterruptedException {
        long end = System.currentTimeMillis() + EngineFixture.TIMEOUT;
        while (System.currentTimeMillis() < end) {
            JsonNode decision = last.get();
            if (decision != null && decision.path("decisions").path(varpoint).asText().replaceFirst("\\.0$", "").equals(value)) {
                return true;
            }
            Thread.sleep(20);
        }
        return false;
    }

    private static JsonNode read(byte[] body) {
        try {
            return Json.MAPPER.readTree(body);
        } catch (java.io.IOException e) {
            return null;
        }
    }

    private static long usedHeapAfterGc() {
        System.gc();
        Runtime rt = Runtime.getRuntime();
        return rt.totalMemory() - rt.freeMemory();
    }
}
