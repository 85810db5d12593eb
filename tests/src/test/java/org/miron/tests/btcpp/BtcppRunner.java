package org.miron.tests.btcpp;

import static org.junit.Assert.assertEquals;
import static org.junit.Assume.assumeTrue;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import org.miron.cli.MironCli;
import org.miron.runtime.Json;
import org.miron.testkit.RepositoryRoot;

/**
 * The real miron-btcpp-run (cpp/miron_btcpp, built on BehaviorTree.CPP 4.8.2 by
 * scripts/ensure-btcpp-plugin.sh) as a process: its JSON lines are collected as they come and
 * can be waited for. Tests are skipped, with the reason, when the runner was not built.
 */
final class BtcppRunner implements AutoCloseable {
    static final Path EXECUTABLE = RepositoryRoot.path().resolve("build/miron-btcpp/miron-btcpp-run");

    private final Process process;
    private final List<JsonNode> lines = new ArrayList<>();
    private final StringBuilder errors = new StringBuilder();

    static void assumeBuilt() {
        assumeTrue("miron-btcpp-run not built (scripts/ensure-btcpp-plugin.sh says why): " + EXECUTABLE,
                Files.isExecutable(EXECUTABLE));
    }

    /** Weaves examples/EXAMPLE (e.g. {@code intralogistics/intralogistics.miron}) as a version-4 tree into {@code out}. */
    static void weaveV4(Path out, String example) {
        assertEquals(0, MironCli.run("generate", "--bt-format", "4", "-o", out.toString(),
                RepositoryRoot.path().resolve("examples/" + example).toString()));
    }

    BtcppRunner(List<String> arguments) throws IOException {
        List<String> command = new ArrayList<>();
        command.add(EXECUTABLE.toString());
        command.addAll(arguments);
        process = new ProcessBuilder(command).start();
        Thread out = new Thread(() -> read(process.getInputStream(), true), "btcpp-out");
        Thread err = new Thread(() -> read(process.getErrorStream(), false), "btcpp-err");
        out.setDaemon(true);
        err.setDaemon(true);
        out.start();
        err.start();
    }

    /** Runs a scripted scenario to its end: one JSON line per tick. */
    static List<JsonNode> scripted(Path scenario) throws Exception {
        try (BtcppRunner runner = new BtcppRunner(List.of("--script", scenario.toString()))) {
            if (!runner.process.waitFor(120, TimeUnit.SECONDS)) {
                throw new AssertionError("the scripted run did not end: " + runner.stderr());
            }
            if (runner.process.exitValue() != 0) {
                throw new AssertionError("the scripted run failed: " + runner.stderr());
            }
            runner.awaitEnd();
            return runner.lines();
        }
    }

    private void read(java.io.InputStream stream, boolean json) {
        try (BufferedReader in = new BufferedReader(new InputStreamReader(stream, StandardCharsets.UTF_8))) {
            String line;
            while ((line = in.readLine()) != null) {
                synchronized (this) {
                    if (json && line.startsWith("{")) {
                        lines.add(Json.MAPPER.readTree(line));
                    } else {
                        errors.append(line).append('\n'); // BehaviorTree.CPP itself prints some warnings on stdout
                    }
                    notifyAll();
                }
            }
        } catch (IOException e) {
            synchronized (this) {
                errors.append("(reading the runner's output: ").append(e).append(")\n");
            }
        }
        synchronized (this) {
            if (json) {
                ended = true;
            }
            notifyAll();
        }
    }

    private boolean ended;

    private synchronized void awaitEnd() throws InterruptedException {
        long end = System.currentTimeMillis() + 30_000;
        while (!ended && System.currentTimeMillis() < end) {
            wait(100);
        }
    }

    synchronized List<JsonNode> lines() {
        return List.copyOf(lines);
    }

    synchronized String stderr() {
        return errors.toString();
    }

    /** The first line matching, waiting up to timeoutMs; fails with the runner's output otherwise. */
    synchronized JsonNode await(String what, Predicate<JsonNode> p, long timeoutMs) throws InterruptedException {
        return await(what, p, timeoutMs, 0);
    }

    /** As {@link #await(String, Predicate, long)}, among the lines from index {@code from} on. */
    synchronized JsonNode await(String what, Predicate<JsonNode> p, long timeoutMs, int from) throws InterruptedException {
        long end = System.currentTimeMillis() + timeoutMs;
        while (true) {
            for (JsonNode line : lines.subList(Math.min(from, lines.size()), lines.size())) {
                if (p.test(line)) {
                    return line;
                }
            }
            long left = end - System.currentTimeMillis();
            if (left <= 0 || ended) {
                throw new AssertionError("no " + what + " from miron-btcpp-run within " + timeoutMs + " ms; out: "
                        + lines.subList(Math.max(0, lines.size() - 40), lines.size()) + "\nerr: " + errors);
            }
            wait(Math.min(left, 200));
        }
    }

    /** SIGTERM, then the runner's stop line (it halts the tree and sends its aborts first). */
    JsonNode stop() throws InterruptedException {
        process.toHandle().destroy(); // SIGTERM; Process.destroy() would also close our end of its output
        if (!process.waitFor(30, TimeUnit.SECONDS)) {
            throw new AssertionError("miron-btcpp-run did not stop on SIGTERM: " + stderr());
        }
        awaitEnd();
        return await("stop line (exit status " + process.exitValue() + ")", l -> l.path("event").asText().equals("stop"), 1000);
    }

    boolean isAlive() {
        return process.isAlive();
    }

    @Override
    public void close() throws InterruptedException {
        if (process.isAlive()) {
            process.destroy();
            if (!process.waitFor(10, TimeUnit.SECONDS)) {
                process.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
            }
        }
    }
}
