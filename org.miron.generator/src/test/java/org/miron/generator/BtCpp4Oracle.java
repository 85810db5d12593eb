package org.miron.generator;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.junit.Assume;

/**
 * The real BehaviorTree.CPP 4 (behaviortreepy in build/btcpp4-venv, scripts/ensure-btcpp4.sh) run
 * on files through org.miron.bt's oracle script: the library's error message per file, null when
 * it loaded.
 */
final class BtCpp4Oracle {
    static final Path PYTHON = Toolchain.ROOT.resolve("build/btcpp4-venv/bin/python");
    static final Path SCRIPT = Toolchain.ROOT.resolve("org.miron.bt/src/test/resources/btcpp4/load_trees.py");

    private BtCpp4Oracle() {
    }

    static void assumeInstalled() {
        if (!Files.isExecutable(PYTHON)) {
            String reason = "BehaviorTree.CPP 4 oracle not installed (" + PYTHON
                    + "; scripts/ensure-btcpp4.sh installs it): test skipped";
            System.out.println(reason);
            Assume.assumeTrue(reason, false);
        }
    }

    static Map<Path, String> rejections(List<Path> files) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(List.of(PYTHON.toString(), SCRIPT.toString()));
        files.forEach(f -> command.add(f.toAbsolutePath().toString()));
        Process process = new ProcessBuilder(command).redirectErrorStream(true).start();
        Map<Path, String> verdicts = new LinkedHashMap<>();
        StringBuilder output = new StringBuilder();
        try (BufferedReader reader = new BufferedReader(
                new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
            String line;
            while ((line = reader.readLine()) != null) {
                output.append(line).append('\n');
                String[] fields = line.split("\t", 3);
                if (fields.length == 3 && (fields[0].equals("loaded") || fields[0].equals("rejected"))) {
                    verdicts.put(Path.of(fields[1]), fields[0].equals("loaded") ? null : fields[2]);
                }
            }
        }
        if (process.waitFor() != 0 || verdicts.size() != files.size()) {
            throw new IllegalStateException("oracle failed:\n" + output);
        }
        return verdicts;
    }
}
