package org.miron.testkit;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The real BehaviorTree.CPP 4 as a loading oracle: does the library accept a tree file, and if not,
 * what does it say? Runs load_trees.py (beside this class) with {@link Btcpp4Python}. Callers first
 * call {@link Btcpp4Python#assumeInstalled()}.
 */
public final class Btcpp4Loader {
    private static Path script;

    /** What the library said about one file: loaded, or rejected with its message. */
    public static final class Verdict {
        public final boolean loaded;
        public final String message;

        Verdict(boolean loaded, String message) {
            this.loaded = loaded;
            this.message = message;
        }
    }

    private Btcpp4Loader() {
    }

    /** Loads the files in one library process; the verdicts in the order of the files. */
    public static Map<File, Verdict> load(List<File> files) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(List.of(Btcpp4Python.location().toString(), script().toString()));
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

    /** The script as a file python can run (the kit may be a jar on the class path). */
    private static synchronized Path script() {
        if (script == null) {
            try (InputStream in = Btcpp4Loader.class.getResourceAsStream("load_trees.py")) {
                Path file = Files.createTempFile("miron-load_trees", ".py");
                file.toFile().deleteOnExit();
                Files.copy(in, file, StandardCopyOption.REPLACE_EXISTING);
                script = file;
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        return script;
    }
}
