package org.miron.testkit.runtime;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * The pyzmq side of the end-to-end benchmarks (docs/performance.md, issue 39):
 * org.miron.runtime/src/test/python/zmq_path.py run by the python of build/pyzmq-venv, which
 * scripts/ensure-pyzmq.sh installs. {@link #floor} measures the libzmq floor of the estimate →
 * variant path (a C proxy and an echo in place of broker and engine), {@link #drive} the same
 * publisher and subscriber against a real broker. Without python or pyzmq every figure is "not
 * measured" with the reason, never an exception.
 */
public final class ZmqPath {
    private final Path python;
    private final Path script;
    private final String missing;

    private ZmqPath(Path python, Path script, String missing) {
        this.python = python;
        this.script = script;
        this.missing = missing;
    }

    /**
     * Runs scripts/ensure-pyzmq.sh (idempotent, instant once installed), then checks what it left.
     * @param root the repository root (RepositoryRoot.path(), which this kit cannot see)
     */
    public static ZmqPath ensure(Path root) {
        Path python = root.resolve("build/pyzmq-venv/bin/python");
        Path script = root.resolve("org.miron.runtime/src/test/python/zmq_path.py");
        String said = "";
        try {
            Process p = new ProcessBuilder("bash", root.resolve("scripts/ensure-pyzmq.sh").toString())
                    .redirectErrorStream(true).redirectInput(ProcessBuilder.Redirect.PIPE).start();
            p.getOutputStream().close();
            said = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
            p.waitFor();
        } catch (IOException e) {
            said = "cannot run scripts/ensure-pyzmq.sh: " + e.getMessage();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        if (Files.isExecutable(python)) {
            return new ZmqPath(python, script, null);
        }
        String[] lines = said.split("\n");
        String reason = lines[lines.length - 1].isBlank() ? "no " + root.relativize(python) : lines[lines.length - 1];
        return new ZmqPath(python, script, reason + " (scripts/ensure-pyzmq.sh)");
    }

    /** Whether the python with pyzmq is there; else every run is "not measured" with the reason. */
    public boolean available() {
        return missing == null;
    }

    /** The libzmq floor: relay and driver of zmq_path.py alone. */
    public Figures floor(int warmup, int rounds) {
        return run(List.of("floor"), warmup, rounds);
    }

    /** The pyzmq driver against a broker's bus endpoints (loopback), the intralogistics engine behind it. */
    public Figures drive(String busIn, String busOut, int warmup, int rounds) {
        return run(List.of("drive", "--in", busIn, "--out", busOut), warmup, rounds);
    }

    private Figures run(List<String> mode, int warmup, int rounds) {
        if (missing != null) {
            return Figures.notMeasured(missing);
        }
        List<String> cmd = new ArrayList<>(List.of(python.toString(), script.toString()));
        cmd.addAll(mode);
        cmd.addAll(List.of("--warmup", Integer.toString(warmup), "--rounds", Integer.toString(rounds)));
        try {
            Process p = new ProcessBuilder(cmd).redirectError(ProcessBuilder.Redirect.INHERIT).start();
            p.getOutputStream().close();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
            p.waitFor(); // the script ends by itself: every wait in it has a timeout
            String[] lines = out.split("\n");
            JsonNode line = new ObjectMapper().readTree(lines[lines.length - 1]);
            if (line == null || line.has("error") || !line.has("p50_ms")) {
                return Figures.notMeasured("zmq_path.py " + mode.get(0) + ": "
                        + (line != null && line.has("error") ? line.get("error").asText() : "no result (exit status " + p.exitValue() + ")"));
            }
            return new Figures(line.get("p50_ms").asDouble(), line.get("p99_ms").asDouble(), line.get("rounds").asInt(),
                    "libzmq " + line.get("libzmq").asText() + ", pyzmq " + line.get("pyzmq").asText(), null);
        } catch (IOException e) {
            return Figures.notMeasured("zmq_path.py " + mode.get(0) + ": " + e.getMessage());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return Figures.notMeasured("interrupted");
        }
    }

    /** p50/p99 in ms of one run of the script, or why there are none. */
    public static final class Figures {
        public final double p50Ms;
        public final double p99Ms;
        public final int rounds;
        /** The libzmq and pyzmq versions that measured them. */
        public final String versions;
        /** Why there are no figures, or null. */
        public final String notMeasured;

        public Figures(double p50Ms, double p99Ms, int rounds, String versions, String notMeasured) {
            this.p50Ms = p50Ms;
            this.p99Ms = p99Ms;
            this.rounds = rounds;
            this.versions = versions;
            this.notMeasured = notMeasured;
        }

        static Figures notMeasured(String reason) {
            return new Figures(Double.NaN, Double.NaN, 0, null, reason);
        }

        public boolean measured() {
            return notMeasured == null;
        }

        /** "x1.23 / x2.05": p50 and p99 as multiples of this floor's, or "" when it was not measured. */
        public String ratios(double p50Ms, double p99Ms) {
            return measured() ? String.format("x%.2f / x%.2f", p50Ms / this.p50Ms, p99Ms / this.p99Ms) : "";
        }
    }
}
