package org.miron.cli.runbench;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * One {@code ./miron COMMAND ...} as a user starts it: a real process whose output lines are read
 * as they come and kept with the time each arrived (System.nanoTime()), so that a start-up can be
 * split at the lines the command prints. The launcher execs java, so the process is the JVM and
 * /proc/PID/status tells its resident memory.
 */
final class LaunchedMiron implements AutoCloseable {
    final String name;
    final long launchedNanos;
    private final Process process;
    private final List<String> lines = new ArrayList<>();
    private final List<Long> arrived = new ArrayList<>();

    /**
     * @param javaToolOptions given to the JVM in JAVA_TOOL_OPTIONS (e.g. a -Xlog), or null: the
     *                        launcher's own flags are left as they are
     */
    LaunchedMiron(Path root, Path dir, String name, String javaToolOptions, String... args) throws IOException {
        this.name = name;
        List<String> cmd = new ArrayList<>(List.of(root.resolve("miron").toString()));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile()).redirectErrorStream(true);
        pb.environment().remove("JAVA_TOOL_OPTIONS");
        if (javaToolOptions != null) {
            pb.environment().put("JAVA_TOOL_OPTIONS", javaToolOptions);
        }
        launchedNanos = System.nanoTime();
        process = pb.start();
        process.getOutputStream().close(); // the components never read standard input
        Thread reader = new Thread(this::read, name + " output");
        reader.setDaemon(true);
        reader.start();
    }

    private void read() {
        try (BufferedReader r = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
            for (String line; (line = r.readLine()) != null;) {
                long at = System.nanoTime();
                synchronized (lines) {
                    lines.add(line);
                    arrived.add(at);
                }
            }
        } catch (IOException e) {
            // the process is gone: what it printed so far is kept
        }
    }

    /** When the first line starting with {@code prefix} arrived (System.nanoTime()), or -1. */
    long lineNanos(String prefix) {
        synchronized (lines) {
            for (int i = 0; i < lines.size(); i++) {
                if (lines.get(i).startsWith(prefix)) {
                    return arrived.get(i);
                }
            }
        }
        return -1;
    }

    /** Waits for the process to end by itself; its exit status. */
    int waitFor() throws InterruptedException {
        return process.waitFor();
    }

    boolean alive() {
        return process.isAlive();
    }

    /** The last lines the process printed, on one line: what to show when it did not come up. */
    String lastWords() {
        synchronized (lines) {
            return lines.isEmpty() ? "(nothing printed)" : String.join(" | ", lines.subList(Math.max(0, lines.size() - 3), lines.size()));
        }
    }

    /** VmRSS and VmHWM of the process in KiB, from /proc/PID/status. */
    long[] residentKiB() throws IOException {
        long rss = -1;
        long hwm = -1;
        for (String line : Files.readAllLines(Path.of("/proc", Long.toString(process.pid()), "status"))) {
            if (line.startsWith("VmRSS:")) {
                rss = kib(line);
            } else if (line.startsWith("VmHWM:")) {
                hwm = kib(line);
            }
        }
        return new long[] { rss, hwm };
    }

    private static long kib(String line) {
        return Long.parseLong(line.replaceAll("\\D+", ""));
    }

    /** SIGTERM, as Ctrl-C would stop it; killed if it has not ended after 10 s. */
    @Override
    public void close() throws InterruptedException {
        process.destroy();
        if (!process.waitFor(10, TimeUnit.SECONDS)) {
            process.destroyForcibly().waitFor();
        }
    }
}
