package org.miron.runtime.player;

import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import java.util.logging.Logger;
import org.miron.runtime.Json;
import org.miron.runtime.bus.BusClient;

/**
 * Publishes a scenario's steps on the bus at their times, standing in for the RoQME QoS Metrics
 * Provider. {@code timeScale} multiplies every {@code at}: 0.5 plays twice as fast, 2 half as fast.
 */
public final class ScenarioPlayer implements AutoCloseable {
    private static final Logger LOG = Logger.getLogger(ScenarioPlayer.class.getName());
    private final Scenario scenario;
    private final double timeScale;
    private final BusClient bus;
    private volatile boolean stopped;

    public ScenarioPlayer(Scenario scenario, double timeScale, String busIn) {
        if (!(timeScale > 0) || Double.isInfinite(timeScale)) {
            throw new IllegalArgumentException("time scale must be a positive number, got " + timeScale);
        }
        this.scenario = scenario;
        this.timeScale = timeScale;
        this.bus = new BusClient("player", busIn, null, List.of(), (t, b) -> { }).start();
    }

    /**
     * Plays to the end (or until {@link #close()}); waits up to {@code connectTimeoutMs} for the
     * broker first. Returns the number of steps published.
     */
    public int play(long connectTimeoutMs) throws InterruptedException {
        if (!bus.awaitReady(connectTimeoutMs)) {
            throw new IllegalStateException("no broker listening on the bus within " + connectTimeoutMs + " ms");
        }
        long start = System.nanoTime();
        int played = 0;
        for (Scenario.Step step : scenario.steps()) {
            long due = start + (long) (step.at() * timeScale * 1_000_000L);
            long waitMs;
            while (!stopped && (waitMs = (due - System.nanoTime()) / 1_000_000L) > 0) {
                Thread.sleep(Math.min(waitMs, 100));
            }
            if (stopped) {
                break;
            }
            ObjectNode body = step.body().deepCopy();
            if (!body.has("time")) {
                body.put("time", System.currentTimeMillis());
            }
            // retained per subject: re-announced to a restarted broker, whose cache starts empty
            bus.publishRetained(step.topic() + "\0" + body.path("namespace").asText("") + "\0"
                    + body.path("name").asText(""), step.topic(), Json.write(body));
            LOG.info("played " + step.topic() + " " + body);
            played++;
        }
        bus.flush(2000);
        return played;
    }

    @Override
    public void close() {
        stopped = true;
        bus.close();
    }
}
