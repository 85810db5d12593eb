package org.miron.cli.faults;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.miron.cli.MironCli;

/**
 * A runtime command ({@code miron broker|engine|skill-mock|play|execute ...}) as a real child
 * JVM on the test class path, its output in files, for process-level faults: SIGTERM, kill -9,
 * restart on the same endpoints.
 */
final class RuntimeProcess implements AutoCloseable {
    private final Process process;
    private final Path out;

    private RuntimeProcess(Process process, Path out) {
        this.process = process;
        this.out = out;
    }

    /** Starts the command; stdout and stderr (the log) go to {@code dir/<name>-<n>.log}. */
    static RuntimeProcess start(Path dir, String name, String... args) throws IOException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx128m", "-XX:TieredStopAtLevel=1", "-cp", System.getProperty("java.class.path"),
                MironCli.class.getName()));
        cmd.addAll(List.of(args));
        Path log = Files.createTempFile(dir, name + "-", ".log");
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        p.getOutputStream().close(); // the commands must not need stdin
        return new RuntimeProcess(p, log);
    }

    /** Waits until the output contains {@code text}; false on timeout or if the process ended. */
    boolean awaitOutput(String text, long timeoutMs) throws InterruptedException {
        long end = System.currentTimeMillis() + timeoutMs;
        while (System.currentTimeMillis() < end) {
            if (output().contains(text)) {
                return true;
            }
            if (!process.isAlive()) {
                return output().contains(text);
            }
            Thread.sleep(20);
        }
        return false;
    }

    String output() {
        try {
            return Files.readString(out, StandardCharsets.UTF_8);
        } catch (IOException e) {
            return "";
        }
    }

    /** Waits for the command to end by itself: its exit status, -1 if it did not end in time. */
    int awaitExit(long timeoutMs) throws InterruptedException {
        return process.waitFor(timeoutMs, TimeUnit.MILLISECONDS) ? process.exitValue() : -1;
    }

    /** SIGTERM, then the exit status (-1 if it did not end in time). */
    int terminate(long timeoutMs) throws InterruptedException {
        process.destroy();
        return process.waitFor(timeoutMs, TimeUnit.MILLISECONDS) ? process.exitValue() : -1;
    }

    /** kill -9: no shutdown hook, sockets vanish without a goodbye. */
    void kill() throws InterruptedException {
        process.destroyForcibly();
        process.waitFor(20, TimeUnit.SECONDS);
    }

    long pid() {
        return process.pid();
    }

    boolean isAlive() {
        return process.isAlive();
    }

    @Override
    public void close() throws InterruptedException {
        kill();
    }
}
