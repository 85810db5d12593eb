package org.miron.cli.monitor;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.io.StringWriter;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.miron.cli.MironCli;
import org.miron.testkit.RepositoryRoot;

import picocli.CommandLine;

/**
 * `miron demo --monitor 0` on the hospital example, run in a thread of the test's JVM as the
 * command line runs it: what it prints, the monitor's address once it serves, its exit status.
 */
final class MonitoredDemo {
    private static final Pattern URL = Pattern.compile("live monitor on (http://127\\.0\\.0\\.1:\\d+/)");
    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();
    private final AtomicInteger status = new AtomicInteger(-1);
    private final Thread thread;

    /** Starts the demo of the hospital example writing into {@code dir} at {@code timeScale}. */
    MonitoredDemo(String dir, String timeScale) {
        this(RepositoryRoot.resolve("examples/hospital-delivery/hospital.miron"), dir, timeScale);
    }

    /** The same on another model (a copy of the example, say, with a requirement of the test's own). */
    MonitoredDemo(Path model, String dir, String timeScale) {
        CommandLine cli = MironCli.commandLine();
        cli.setOut(new PrintWriter(out, true));
        cli.setErr(new PrintWriter(err, true));
        thread = new Thread(() -> status.set(cli.execute("demo", "--model", model.toString(), "--out", dir,
                "--time-scale", timeScale, "--monitor", "0")), "demo");
        thread.start();
    }

    /** The monitor's address once the demo prints it; null if the demo ended or the time ran out. */
    String awaitUrl(long timeoutMs) throws InterruptedException {
        long end = System.currentTimeMillis() + timeoutMs;
        while (thread.isAlive() && System.currentTimeMillis() < end) {
            Matcher found = URL.matcher(out.toString());
            if (found.find()) {
                return found.group(1);
            }
            Thread.sleep(20);
        }
        Matcher found = URL.matcher(out.toString());
        return found.find() ? found.group(1) : null;
    }

    /** The exit status once the demo has ended (-1 if it did not within the time). */
    int await(long timeoutMs) throws InterruptedException {
        thread.join(timeoutMs);
        return status.get();
    }

    /** What the demo printed, its standard output then its standard error. */
    String printed() {
        return out + "\n" + err;
    }

    String errors() {
        return err.toString();
    }
}
