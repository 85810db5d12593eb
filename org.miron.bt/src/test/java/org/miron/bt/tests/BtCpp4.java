package org.miron.bt.tests;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.junit.Assume;

/**
 * The real BehaviorTree.CPP 4 as an oracle: behaviortreepy in build/btcpp4-venv (installed by
 * scripts/ensure-btcpp4.sh), driven by src/test/resources/btcpp4/load_trees.py as a process.
 * Public for the other modules' tests (the generator's woven trees).
 */
public final class BtCpp4 {
    static final File SCRIPT = new File(BtFiles.repositoryRoot(), "org.miron.bt/src/test/resources/btcpp4/load_trees.py");

    /** What the library said about one file: loaded, or rejected with its message. */
    public static final class Verdict {
        public final boolean loaded;
        public final String message;

        Verdict(boolean loaded, String message) {
            this.loaded = loaded;
            this.message = message;
        }
    }

    private BtCpp4() {
    }

    static File python() {
        return new File(BtFiles.repositoryRoot(), "build/btcpp4-venv/bin/python");
    }

    /** Skips the calling test, saying why, when the oracle is not installed. */
    public static void assumeInstalled() {
        if (!python().canExecute()) {
            String reason = "BehaviorTree.CPP 4 oracle not installed (" + python()
                    + "; scripts/ensure-btcpp4.sh installs it): test skipped";
            System.out.println(reason);
            Assume.assumeTrue(reason, false);
        }
    }

    /** Loads the files in one library process; the verdicts in the order of the files. */
    public static Map<File, Verdict> load(List<File> files) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(List.of(python().getPath(), SCRIPT.getAbsolutePath()));
        Map<String, File> byPath = new LinkedHashMap<>();
        for (File file : files) {
            command.add(file.getAbsolutePath());
            byPath.put(file.getAbsolutePath(), file);
        }
        Process process = new ProcessBuilder(command).redirectErrorStream(true).start();
        Map<File, Verdict> verdicts = new LinkedHashMap<>();
        StringBuilder output = new StringBuilder();
        try (BufferedReader reader = new BufferedReader(
                new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
            String line;
            while ((line = reader.readLine()) != null) {
                output.append(line).append('\n');
                // The library also prints warnings to stdout: only verdict lines count.
                String[] fields = line.split("\t", 3);
                if (fields.length == 3 && byPath.containsKey(fields[1])
                        && (fields[0].equals("loaded") || fields[0].equals("rejected"))) {
                    verdicts.put(byPath.get(fields[1]), new Verdict(fields[0].equals("loaded"), fields[2]));
                }
            }
        }
        int exit = process.waitFor();
        if (exit != 0 || verdicts.size() != files.size()) {
            throw new IllegalStateException("oracle exited with " + exit + ":\n" + output);
        }
        return verdicts;
    }
}
