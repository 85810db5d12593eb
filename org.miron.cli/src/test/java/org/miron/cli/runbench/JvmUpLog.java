package org.miron.cli.runbench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * When a JVM was up, as the JVM itself says: its class-load log ({@link #option}, given in
 * JAVA_TOOL_OPTIONS) stamps each line with System.nanoTime()'s clock (CLOCK_MONOTONIC, the same in
 * every process of this machine) and the JVM's own uptime. The JVM started at stamp minus uptime;
 * it is up when it loads the main class, org.miron.cli.MironCli, whose main then starts the command.
 */
final class JvmUpLog {
    static final String MAIN = "org.miron.cli.MironCli";
    private static final Pattern LINE = Pattern.compile("^\\[(\\d+)ns\\]\\[(\\d+)ns\\] (\\S+) ");

    final long startNanos;
    final long upNanos;

    private JvmUpLog(long startNanos, long upNanos) {
        this.startNanos = startNanos;
        this.upNanos = upNanos;
    }

    /** The -Xlog option that writes the log to {@code file}. */
    static String option(Path file) {
        return "-Xlog:class+load=info:file=" + file + ":timenanos,uptimenanos";
    }

    /** Reads the log; an IllegalStateException when the main class never loaded. */
    static JvmUpLog read(Path file) throws IOException {
        List<String> lines = Files.readAllLines(file);
        long start = -1;
        for (String line : lines) {
            Matcher m = LINE.matcher(line);
            if (!m.find()) {
                continue;
            }
            if (start < 0) {
                start = Long.parseLong(m.group(1)) - Long.parseLong(m.group(2));
            }
            if (m.group(3).equals(MAIN)) {
                return new JvmUpLog(start, Long.parseLong(m.group(1)));
            }
        }
        throw new IllegalStateException(file + ": " + MAIN + " was never loaded");
    }
}
