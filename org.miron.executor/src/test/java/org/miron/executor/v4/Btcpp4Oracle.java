package org.miron.executor.v4;

import static org.junit.Assume.assumeTrue;

import java.io.IOException;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * The real BehaviorTree.CPP 4 (behaviortreepy in {@code <miron.root>/build/btcpp4-venv}, made by
 * scripts/ensure-btcpp4.sh) running a scenario through btcpp4_oracle.py. Tests using it are
 * skipped, with the reason printed, when the venv is missing.
 */
final class Btcpp4Oracle {
    private static final ObjectMapper JSON = new ObjectMapper();

    private Btcpp4Oracle() {
    }

    static Path python() {
        Path root = Path.of(System.getProperty("miron.root", "../..")).toAbsolutePath().normalize();
        Path python = root.resolve("build/btcpp4-venv/bin/python");
        if (!Files.isExecutable(python)) {
            System.out.println("SKIPPED: BehaviorTree.CPP 4 oracle tests: no " + python
                    + " (run scripts/ensure-btcpp4.sh, which needs pip to reach behaviortreepy)");
        }
        assumeTrue("no BehaviorTree.CPP 4 oracle at " + python, Files.isExecutable(python));
        return python;
    }

    static Path resource(String name) {
        try {
            return Path.of(Btcpp4Oracle.class.getResource("/btcpp4/" + name).toURI());
        } catch (URISyntaxException | NullPointerException e) {
            throw new IllegalArgumentException("no test resource btcpp4/" + name, e);
        }
    }

    /** The library's ticks for a scenario file. */
    static List<TickRecord> run(Path scenario) throws IOException, InterruptedException {
        Process process = new ProcessBuilder(python().toString(), resource("btcpp4_oracle.py").toString(), scenario.toString())
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
