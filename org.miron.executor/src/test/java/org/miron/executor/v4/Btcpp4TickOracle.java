package org.miron.executor.v4;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.miron.testkit.Btcpp4Python;

import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * The real BehaviorTree.CPP 4 as a ticking oracle: runs a scenario through btcpp4_oracle.py with
 * the python of {@link Btcpp4Python} and returns the library's ticks. (The loading oracle, does
 * the library accept a file, is the test kit's Btcpp4Loader.) Tests using it are skipped, with the
 * reason printed, when the python is missing.
 */
final class Btcpp4TickOracle {
    private static final ObjectMapper JSON = new ObjectMapper();

    private Btcpp4TickOracle() {
    }

    static Path resource(String name) {
        try {
            return Path.of(Btcpp4TickOracle.class.getResource("/btcpp4/" + name).toURI());
        } catch (URISyntaxException | NullPointerException e) {
            throw new IllegalArgumentException("no test resource btcpp4/" + name, e);
        }
    }

    /** The library's ticks for a scenario file. */
    static List<TickRecord> run(Path scenario) throws IOException, InterruptedException {
        Path python = Btcpp4Python.assumeInstalled();
        Process process = new ProcessBuilder(python.toString(), resource("btcpp4_oracle.py").toString(), scenario.toString())
                .redirectErrorStream(false)
                .start();
        byte[] out = process.getInputStream().readAllBytes();
        String err = new String(process.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        if (!process.waitFor(60, TimeUnit.SECONDS)) {
            process.destroyForcibly();
            throw new IllegalStateException("the oracle did not finish for " + scenario);
        }
        if (process.exitValue() != 0) {
            throw new IllegalStateException("the oracle failed on " + scenario + ":\n" + err);
        }
        List<TickRecord> ticks = new ArrayList<>();
        for (String line : new String(out, StandardCharsets.UTF_8).split("\n")) {
            if (!line.isBlank()) {
                ticks.add(JSON.readValue(line, TickRecord.class));
            }
        }
        return ticks;
    }
}
