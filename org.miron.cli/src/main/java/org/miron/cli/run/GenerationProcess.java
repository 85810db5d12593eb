package org.miron.cli.run;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * {@code miron generate} in a JVM of its own, on this one's class path: the run-time process
 * never loads Xtext, EMF or Guice (their classes and the heap the parse and validation touched
 * would stay resident for as long as the robot runs). The model's diagnostics are passed on as
 * they come, in the {@code file:line:col: error [code]: message} form.
 */
final class GenerationProcess {
    /** This JVM's options the generation's keeps: stack size, class-data archive, MIRoN's properties. */
    private static final String[] KEPT = { "-Xss", "-XX:SharedArchiveFile=", "-XX:+UnlockDiagnosticVMOptions",
            "-XX:ArchiveRelocationMode=", "-Xlog:cds", "-Dmiron.", "-Dguice" };

    private GenerationProcess() {
    }

    /** Generates model into out, listing what it read in inputs; returns miron generate's exit status. */
    static int run(Path model, Path out, Path inputs, PrintWriter err) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>();
        command.add(ProcessHandle.current().info().command().orElse(Path.of(System.getProperty("java.home"), "bin", "java").toString()));
        for (String arg : ManagementFactory.getRuntimeMXBean().getInputArguments()) {
            for (String kept : KEPT) {
                if (arg.startsWith(kept)) {
                    command.add(arg);
                    break;
                }
            }
        }
        command.add("-XX:TieredStopAtLevel=1"); // short-lived, as miron check and miron generate are run
        command.addAll(List.of("-cp", System.getProperty("java.class.path"), "org.miron.cli.MironCli", "generate",
                model.toString(), "-o", out.toString(), "--inputs", inputs.toString()));
        ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true);
        pb.environment().remove("JAVA_TOOL_OPTIONS"); // a profiler's or logger's options are for the run itself
        Process p = pb.start();
        p.getOutputStream().close();
        try (BufferedReader lines = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
            for (String line; (line = lines.readLine()) != null;) {
                if (!line.startsWith("wrote ")) { // diagnostics; the files written are ours to know
                    err.println(line);
                    err.flush();
                }
            }
        } finally {
            if (p.isAlive() && !p.waitFor(10, java.util.concurrent.TimeUnit.SECONDS)) {
                p.destroyForcibly();
            }
        }
        return p.waitFor();
    }
}
