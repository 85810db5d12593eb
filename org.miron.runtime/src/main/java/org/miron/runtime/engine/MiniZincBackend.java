package org.miron.runtime.engine;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

/**
 * Runs the real {@code minizinc} binary per solve: argument list (no shell), Gecode, a time
 * limit, JSON stream output, parameters in a JSON data file ({@code -d params.json}: a command-line
 * argument fails past ≈ 780 varpoints with "Argument list too long"). A watchdog kills the
 * process if it overruns the limit by more than {@code GRACE_MS} (a hung solver or flattening).
 *
 * <p>A time limit of 0 or less means automatic: {@link #autoTimeLimitMs}. MiniZinc's limit covers
 * flattening, which grows with the model (≈ 5 s for 1 000 numeric varpoints with 4 rules each).
 */
public final class MiniZincBackend implements SolverBackend {
    private static final long GRACE_MS = 3000;
    private static final int STDERR_TAIL = 2000;

    private final IoModel model;
    private final String executable;
    private final String solver;
    private final long timeLimitMs;

    public MiniZincBackend(IoModel model, String executable, String solver, long timeLimitMs) {
        this.model = model;
        this.executable = executable;
        this.solver = solver;
        this.timeLimitMs = timeLimitMs > 0 ? timeLimitMs : autoTimeLimitMs(model.varpoints().size());
    }

    /** 2 s plus 25 ms per varpoint: room for flattening large models on a slow or busy machine. */
    public static long autoTimeLimitMs(int varpoints) {
        return 2000 + 25L * varpoints;
    }

    public long timeLimitMs() {
        return timeLimitMs;
    }

    @Override
    public String name() {
        return "minizinc";
    }

    @Override
    public void check() throws BackendUnavailableException {
        String hint = "; install MiniZinc (e.g. apt-get install minizinc) or give its path with --minizinc";
        try {
            Process p = new ProcessBuilder(List.of(executable, "--version")).redirectErrorStream(true).start();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            if (!p.waitFor(20, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                throw new BackendUnavailableException("'" + executable + " --version' did not answer" + hint);
            }
            if (p.exitValue() != 0 || !out.contains("MiniZinc")) {
                throw new BackendUnavailableException("'" + executable + "' does not look like MiniZinc (exit "
                        + p.exitValue() + ")" + hint);
            }
        } catch (IOException e) {
            throw new BackendUnavailableException("cannot run MiniZinc executable '" + executable + "': "
                    + e.getMessage() + hint);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new BackendUnavailableException("interrupted while checking MiniZinc");
        }
    }

    List<String> command(Path paramsFile) {
        List<String> cmd = new ArrayList<>(List.of(executable, "--solver", solver,
                "--json-stream", "--output-mode", "json", "--time-limit", Long.toString(timeLimitMs)));
        if (model.dzn() != null) {
            cmd.add("-d");
            cmd.add(model.dzn().toString());
        }
        cmd.add("-d");
        cmd.add(paramsFile.toString()); // the .json suffix makes MiniZinc read it as JSON data
        cmd.add(model.mzn().toString());
        return cmd;
    }

    /** Solves with rule priority: conflicting lower rules are dropped ({@link RulePriority}). */
    @Override
    public SolveResult solve(Map<String, Object> params) {
        return RulePriority.solve(model.rules(), params, this::solveOnce);
    }

    /** One minizinc run; the parameters include every rule's keep flag. */
    private SolveResult solveOnce(Map<String, Object> params) {
        long start = System.nanoTime();
        Path paramsFile;
        String data;
        try {
            data = MiniZincData.json(params);
        } catch (IllegalArgumentException e) {
            return SolveResult.failed(SolveResult.Status.ERROR, e.getMessage(), 0);
        }
        try {
            paramsFile = Files.createTempFile("miron-params-", ".json");
            Files.writeString(paramsFile, data);
        } catch (IOException e) {
            return SolveResult.failed(SolveResult.Status.ERROR, "cannot write the parameters: " + e.getMessage(), 0);
        }
        try {
            return run(paramsFile, start);
        } finally {
            try {
                Files.deleteIfExists(paramsFile);
            } catch (IOException ignored) {
                // a temp file left behind is harmless
            }
        }
    }

    private SolveResult run(Path paramsFile, long start) {
        Process p;
        try {
            p = new ProcessBuilder(command(paramsFile)).start();
        } catch (IOException e) {
            return SolveResult.failed(SolveResult.Status.ERROR, "cannot start minizinc: " + e.getMessage(), 0);
        }
        try { // the engine never feeds stdin
            p.getOutputStream().close();
        } catch (IOException ignored) {
            // nothing to close
        }
        MiniZincOutput output = new MiniZincOutput();
        StringBuilder stderr = new StringBuilder();
        Thread outReader = reader(p.getInputStream(), output::line, "minizinc-out");
        Thread errReader = reader(p.getErrorStream(), l -> appendTail(stderr, l), "minizinc-err");
        try {
            boolean done = p.waitFor(timeLimitMs + GRACE_MS, TimeUnit.MILLISECONDS);
            if (!done) {
                kill(p);
                p.waitFor(2, TimeUnit.SECONDS);
                return SolveResult.failed(SolveResult.Status.TIMEOUT,
                        "minizinc killed after " + (timeLimitMs + GRACE_MS) + " ms", millisSince(start));
            }
            outReader.join(2000);
            errReader.join(2000);
        } catch (InterruptedException e) {
            kill(p);
            Thread.currentThread().interrupt();
            return SolveResult.failed(SolveResult.Status.ERROR, "solve interrupted", millisSince(start));
        }
        String errTail;
        synchronized (stderr) {
            errTail = stderr.toString();
        }
        return output.result(model, p.exitValue(), errTail, millisSince(start));
    }

    /** minizinc runs the solver as a child process: kill the whole tree, not just minizinc. */
    private static void kill(Process p) {
        p.descendants().forEach(ProcessHandle::destroyForcibly);
        p.destroyForcibly();
    }

    private static void appendTail(StringBuilder b, String line) {
        synchronized (b) {
            b.append(line).append('\n');
            if (b.length() > STDERR_TAIL) {
                b.delete(0, b.length() - STDERR_TAIL);
            }
        }
    }

    private static Thread reader(InputStream in, java.util.function.Consumer<String> sink, String name) {
        Thread t = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8))) {
                String line;
                while ((line = r.readLine()) != null) {
                    sink.accept(line);
                }
            } catch (IOException ignored) {
                // process killed: what was read is what we have
            }
        }, name);
        t.setDaemon(true);
        t.start();
        return t;
    }

    private static long millisSince(long startNanos) {
        return TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - startNanos);
    }
}
