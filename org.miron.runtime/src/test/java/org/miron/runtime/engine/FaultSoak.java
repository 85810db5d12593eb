package org.miron.runtime.engine;

import com.fasterxml.jackson.databind.JsonNode;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import java.util.logging.Level;
import java.util.logging.Logger;
import org.miron.runtime.Json;
import org.miron.runtime.broker.Broker;
import org.miron.runtime.bus.BusClient;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.skill.SkillInterfaceMock;
import org.miron.runtime.skill.SkillTable;
import org.miron.testkit.runtime.EngineFixture;

/**
 * Fault mode of the soak ({@code gradle :org.miron.runtime:soak -Pfaults=true -Pminutes=N}): broker,
 * engine (real minizinc) and skill interface mock on loopback; random inputs are streamed, then,
 * once the engine has decided them, one component chosen at random is killed and restarted on
 * the same endpoints (closed without a goodbye to its peers, a new instance bound in its place).
 * Inputs are not changed while a fault is being recovered, so the right decision is known. It
 * prints:
 * <ul>
 * <li>decisions lost: gaps in {@code seq} seen by a subscriber that stays up (per engine run: a
 *     restarted engine starts again at 1);</li>
 * <li>wrong-branch episodes: decisions (or re-published ones) during a recovery whose task is
 *     not the one the current inputs call for;</li>
 * <li>time to recover (p50/max) per fault kind: broker, until a subscriber joining after the
 *     restart gets the current decision from the new broker; engine, until the new engine's
 *     first decision; skill interface, until a change-parameter made after the restart is applied
 *     by the new instance.</li>
 * </ul>
 */
final class FaultSoak {
    private static final long TIMEOUT = 20_000;

    private final Path dir;
    private final Random random = new Random(7);
    private final EngineFixture f;
    private Broker broker;
    private SkillInterfaceMock skills;
    private Engine engine;
    private BusClient roqme;
    private BusClient watcher;
    // truth: the latest inputs published
    private double power = 0.5;
    private double safety = 0.5;
    private int battery = 50;
    // what the watcher saw (guarded by this)
    private JsonNode lastDecision;
    private long lastSeq;
    private long lost;
    private long decisions;
    private boolean recovering;
    private boolean wrongEpisode;
    private long wrongBranch;
    private final List<Long> brokerMs = new ArrayList<>();
    private final List<Long> engineMs = new ArrayList<>();
    private final List<Long> skillMs = new ArrayList<>();
    private long unrecovered;

    private FaultSoak(Path dir) throws Exception {
        this.dir = dir;
        this.f = new EngineFixture(dir);
    }

    static boolean run(double minutes) throws Exception {
        Logger.getLogger("").setLevel(Level.SEVERE);
        return new FaultSoak(Files.createTempDirectory("miron-fault-soak")).soak(minutes);
    }

    private String expectedTask() {
        return power < 0.3 || battery < 5 ? "dock" : "pickDeliverCharge";
    }

    private boolean soak(double minutes) throws Exception {
        broker = new Broker(f.endpoints).start();
        skills = new SkillInterfaceMock(f.endpoints.skill(), f.endpoints.skillEvents(), SkillTable.defaults()).start();
        engine = Engine.create(f.options()).start();
        roqme = new BusClient("soak-roqme", f.endpoints.busIn(), null, List.of(), (t, b) -> { }).start();
        watcher = new BusClient("soak-watch", f.endpoints.busIn(), f.endpoints.busOut(), List.of(Topics.DECISION),
                (topic, body) -> onDecision(read(body))).start();
        long end = System.currentTimeMillis() + (long) (minutes * 60_000);
        int faults = 0;
        while (System.currentTimeMillis() < end) {
            stream(1000 + random.nextInt(2000));
            if (!settled(TIMEOUT)) {
                unrecovered++;
                continue;
            }
            faults++;
            switch (random.nextInt(3)) {
                case 0 -> restartBroker();
                case 1 -> restartEngine();
                default -> restartSkills();
            }
        }
        report(faults);
        for (AutoCloseable c : new AutoCloseable[] {watcher, roqme, engine, skills, broker}) {
            c.close();
        }
        return lost == 0 && wrongBranch == 0 && unrecovered == 0 && max(brokerMs) <= 2000 && max(engineMs) <= 2000
                && max(skillMs) <= 2000;
    }

    private void stream(long ms) throws InterruptedException {
        long end = System.currentTimeMillis() + ms;
        while (System.currentTimeMillis() < end) {
            switch (random.nextInt(3)) {
                case 0 -> {
                    power = Math.round(random.nextDouble() * 100) / 100.0;
                    estimate("power_autonomy", power);
                }
                case 1 -> {
                    safety = Math.round(random.nextDouble() * 100) / 100.0;
                    estimate("safety", safety);
                }
                default -> {
                    battery = random.nextInt(101);
                    roqme.publishRetained(Topics.CONTEXT + "/BatteryLevel", Topics.CONTEXT, "{\"name\":\"BatteryLevel\","
                            + "\"namespace\":\"Intralogistics\",\"type\":\"number\",\"value\":" + battery + "}");
                }
            }
            Thread.sleep(50);
        }
    }

    private void estimate(String name, double value) {
        // retained: a restarted broker gets it again, as from the scenario player
        roqme.publishRetained(Topics.ESTIMATE + "/" + name, Topics.ESTIMATE, "{\"name\":\"" + name
                + "\",\"namespace\":\"Intralogistics\",\"value\":" + value + "}");
    }

    /** Whether the latest decision seen is the one for the current inputs. */
    private synchronized boolean current(JsonNode d) {
        if (d == null) {
            return false;
        }
        JsonNode in = d.path("inputs");
        return in.path("metric_Intralogistics_power_autonomy").asDouble() == power
                && in.path("metric_Intralogistics_safety").asDouble() == safety
                && in.path("context_Intralogistics_BatteryLevel").asDouble() == battery
                && d.path("decisions").path("task").asText().equals(expectedTask());
    }

    private boolean settled(long timeoutMs) throws InterruptedException {
        long end = System.currentTimeMillis() + timeoutMs;
        while (System.currentTimeMillis() < end) {
            synchronized (this) {
                if (current(lastDecision)) {
                    return true;
                }
            }
            Thread.sleep(10);
        }
        return false;
    }

    private synchronized void onDecision(JsonNode d) {
        if (d == null) {
            return;
        }
        long seq = d.path("seq").asLong();
        if (seq == 1 && lastSeq > 1) {
            lastSeq = 0; // a restarted engine numbers from 1 again
        }
        if (lastSeq != 0 && seq > lastSeq + 1) {
            lost += seq - lastSeq - 1;
        }
        lastSeq = Math.max(lastSeq, seq);
        decisions++;
        lastDecision = d;
        if (recovering && !d.path("decisions").path("task").asText().equals(expectedTask())) {
            if (!wrongEpisode) {
                wrongBranch++;
            }
            wrongEpisode = true;
        }
        notifyAll();
    }

    private synchronized void beginRecovery() {
        recovering = true;
        wrongEpisode = false;
    }

    private synchronized void endRecovery() {
        recovering = false;
    }

    private void restartBroker() throws Exception {
        beginRecovery();
        broker.close();
        long t0 = System.nanoTime();
        broker = new Broker(f.endpoints).start();
        JsonNode[] seen = new JsonNode[1];
        try (BusClient late = new BusClient("soak-late", f.endpoints.busIn(), f.endpoints.busOut(),
                List.of(Topics.DECISION), (t, b) -> {
                    synchronized (seen) {
                        seen[0] = read(b);
                    }
                }).start()) {
            long end = System.currentTimeMillis() + TIMEOUT;
            boolean ok = false;
            while (!ok && System.currentTimeMillis() < end) {
                synchronized (seen) {
                    ok = current(seen[0]);
                }
                Thread.sleep(5);
            }
            record(ok, brokerMs, t0);
        }
        settled(TIMEOUT); // the watcher, reconnected, is current again
        endRecovery();
    }

    private void restartEngine() throws Exception {
        beginRecovery();
        engine.close();
        long t0 = System.nanoTime();
        engine = Engine.create(f.options()).start();
        long end = System.currentTimeMillis() + TIMEOUT;
        boolean ok = false;
        while (!ok && System.currentTimeMillis() < end) {
            synchronized (this) {
                ok = lastSeq == 1 && current(lastDecision);
            }
            Thread.sleep(5);
        }
        record(ok, engineMs, t0);
        endRecovery();
    }

    private void restartSkills() throws Exception {
        skills.close();
        long t0 = System.nanoTime();
        skills = new SkillInterfaceMock(f.endpoints.skill(), f.endpoints.skillEvents(), SkillTable.defaults()).start();
        // a new maxVelocity decision must reach the new instance
        double next = safety >= 0.5 ? 0.11 : 0.89;
        safety = next;
        estimate("safety", safety);
        double transvel = 10 + Math.floor(90.0 * next);
        record(skills.awaitChange(c -> c.value() == transvel, TIMEOUT).isPresent(), skillMs, t0);
    }

    private void record(boolean ok, List<Long> times, long t0) {
        if (ok) {
            times.add((System.nanoTime() - t0) / 1_000_000L);
        } else {
            unrecovered++;
        }
    }

    private void report(int faults) {
        System.out.printf("soak faults: %d faults injected (broker %d, engine %d, skill interface %d), %d decisions seen%n",
                faults, brokerMs.size(), engineMs.size(), skillMs.size(), decisions);
        System.out.printf("soak faults: decisions lost (seq gaps) %d, wrong-branch episodes %d, not recovered in %d s: %d%n",
                lost, wrongBranch, TIMEOUT / 1000, unrecovered);
        System.out.printf("soak faults: time to recover p50/max: broker %s, engine %s, skill interface %s%n",
                p50max(brokerMs), p50max(engineMs), p50max(skillMs));
    }

    private static String p50max(List<Long> ms) {
        if (ms.isEmpty()) {
            return "-";
        }
        List<Long> sorted = new ArrayList<>(ms);
        Collections.sort(sorted);
        return sorted.get(sorted.size() / 2) + "/" + sorted.get(sorted.size() - 1) + " ms";
    }

    private static long max(List<Long> ms) {
        return ms.isEmpty() ? 0 : Collections.max(ms);
    }

    private static JsonNode read(byte[] body) {
        try {
            return Json.MAPPER.readTree(body);
        } catch (java.io.IOException e) {
            return null;
        }
    }
}
