package org.miron.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.Endpoints;
import org.miron.runtime.bus.BusClient;

/** The broker as a real process: ignores a closed stdin, serves, stops cleanly on SIGTERM. */
public class ProcessShutdownTest {
    @Rule
    public TemporaryFolder tmp = new TemporaryFolder();


    @Test
    public void brokerRunsWithoutStdinAndStopsCleanlyOnSigterm() throws Exception {
        Endpoints ep = Endpoints.freeLoopback();
        Path err = tmp.getRoot().toPath().resolve("stderr.txt");
        Process p = new ProcessBuilder(List.of(
                Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp", CliProcess.classpath(),
                MironCli.class.getName(), "broker", "--request", ep.request(), "--skill", ep.skill(),
                "--bus-in", ep.busIn(), "--bus-out", ep.busOut()))
                .redirectError(err.toFile()).redirectOutput(tmp.getRoot().toPath().resolve("stdout.txt").toFile())
                .start();
        try {
            p.getOutputStream().close(); // EOF on stdin must not stop it
            try (BusClient client = new BusClient("probe", ep.busIn(), null, List.of(), (t, b) -> { }).start()) {
                assertTrue("broker serves the bus: " + read(err), client.awaitReady(20_000));
            }
            assertTrue(p.isAlive());
            p.destroy(); // SIGTERM
            assertTrue("stops on SIGTERM", p.waitFor(20, TimeUnit.SECONDS));
            assertEquals("JVM exit status after SIGTERM", 143, p.exitValue());
            String stderr = read(err);
            assertFalse(stderr, stderr.contains("Exception"));
            assertFalse(stderr, stderr.contains("SEVERE"));
        } finally {
            p.destroyForcibly();
        }
    }

    private static String read(Path file) throws Exception {
        return Files.exists(file) ? Files.readString(file, StandardCharsets.UTF_8) : "";
    }
}
