package org.miron.cli.demo;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.miron.runtime.Endpoints;
import org.miron.runtime.Json;

/**
 * The demo's robot on the real BehaviorTree.CPP 4: miron-btcpp-run (cpp/miron_btcpp) as a child
 * process on the demo's endpoints, repeating the mission until stopped. Its JSON lines are told
 * like the Java executor's: each pushed skill with its in-attributes, each finished mission.
 */
final class BtcppExecutor implements AutoCloseable {
    private final List<String> command = new ArrayList<>();
    private final Narrator narrator;
    private final BusRecorder clock;
    private final AtomicInteger missions = new AtomicInteger();
    private final StringBuilder errors = new StringBuilder();
    private Process process;
    private Thread reader;

    /** Attaches BehaviorTree.CPP's Groot2Publisher on this port (and the next); before {@link #start}. */
    BtcppExecutor groot(int port) {
        command.addAll(List.of("--groot", Integer.toString(port)));
        return this;
    }

    /** Records the run with BehaviorTree.CPP's FileLogger2 into this .btlog; before {@link #start}. */
    BtcppExecutor record(Path btlog) {
        command.addAll(List.of("--record", btlog.toAbsolutePath().toString()));
        return this;
    }

    BtcppExecutor(Path runner, Path tree, Endpoints endpoints, Narrator narrator, BusRecorder clock) {
        command.addAll(List.of(runner.toString(), tree.toString(), "--bus", endpoints.busOut(), "--skill-requests",
                endpoints.request(), "--skill-results", endpoints.skillEvents(), "--period", "50", "--repeat"));
        this.narrator = narrator;
        this.clock = clock;
    }

    void start() throws IOException {
        process = new ProcessBuilder(command).start();
        reader = new Thread(this::read, "demo-btcpp-out");
        reader.setDaemon(true);
        reader.start();
        Thread err = new Thread(() -> {
            try (BufferedReader in = new BufferedReader(new InputStreamReader(process.getErrorStream(), StandardCharsets.UTF_8))) {
                for (String line; (line = in.readLine()) != null;) {
                    synchronized (errors) {
                        errors.append(line).append('\n');
                    }
                }
            } catch (IOException e) {
                // the process ended
            }
        }, "demo-btcpp-err");
        err.setDaemon(true);
        err.start();
    }

    private void read() {
        try (BufferedReader in = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
            for (String line; (line = in.readLine()) != null;) {
                if (line.startsWith("{")) { // BehaviorTree.CPP itself may print plain lines
                    tell(Json.MAPPER.readTree(line));
                }
            }
        } catch (IOException e) {
            // the process ended
        }
    }

    private void tell(JsonNode line) {
        switch (line.path("event").asText()) {
            case "skill" -> {
                StringBuilder what = new StringBuilder(line.path("name").asText());
                line.path("in").fields().forEachRemaining(f -> what.append(' ').append(f.getKey()).append('=').append(f.getValue().asText()));
                narrator.say(clock.elapsed(), "ROBOT ", what.toString());
            }
            case "mission" -> {
                missions.incrementAndGet();
                narrator.say(clock.elapsed(), "ROBOT ", "mission " + line.path("status").asText() + ", starting again");
            }
            case "error" -> narrator.say(clock.elapsed(), "ROBOT ", "BehaviorTree.CPP: " + line.path("message").asText());
            default -> {
            }
        }
    }

    /** SIGTERM (the runner halts the tree, aborting running skills) and the missions finished. */
    int stop() throws InterruptedException {
        if (process != null && process.isAlive()) {
            process.toHandle().destroy(); // not Process.destroy(): it would close the output we still read
            if (!process.waitFor(15, TimeUnit.SECONDS)) {
                process.destroyForcibly();
            }
            reader.join(5000);
        }
        return missions.get();
    }

    /** What the runner logged, for error messages. */
    String errors() {
        synchronized (errors) {
            return errors.toString();
        }
    }

    @Override
    public void close() throws InterruptedException {
        stop();
    }
}
