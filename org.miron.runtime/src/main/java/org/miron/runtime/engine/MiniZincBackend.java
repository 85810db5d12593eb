package org.miron.runtime.engine;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.miron.runtime.Json;

/**
 * Runs the real {@code minizinc} binary per solve: argument list (no shell), Gecode, a time
 * limit, JSON stream output, parameters as {@code --cmdline-json-data}. A watchdog kills the
 * process if it overruns the limit by more than {@code GRACE_MS} (a hung solver or flattening).
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
        this.timeLimitMs = timeLimitMs;
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

    List<String> command(Map<String, Object> params) {
        List<String> cmd = new ArrayList<>(List.of(executable, "--solver", solver,
                "--json-stream", "--output-mode", "json", "--time-limit", Long.toString(timeLimitMs)));
        if (model.dzn() != null) {
            cmd.add("-d");
            cmd.add(model.dzn().toString());
        }
        cmd.add("--cmdline-json-data");
        cmd.add(Json.write(params));
        cmd.add(model.mzn().toString());
        return cmd;
    }

    @Override
    public SolveResult solve(Map<String, Object> params) {
        long start = System.nanoTime();
        Process p;
        try {
            p = new ProcessBuilder(command(params)).start();
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
