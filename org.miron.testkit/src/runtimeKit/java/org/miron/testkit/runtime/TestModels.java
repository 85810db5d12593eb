package org.miron.testkit.runtime;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.List;

/**
 * The runtime's small test models, beside this class: in models/ the engine's testbot, whose rules
 * {@link TestbotRules} also states in Java, and portbot; in roqme/ hand-written RoQME runtime models
 * (worked.roqme.json with its trace worked.trace.jsonl, intralogistics.roqme.json). Copied into a
 * folder a test owns, so it may change or corrupt them, or read as text.
 */
public final class TestModels {
    private TestModels() {
    }

    /** Copies the model's .io.json, .mzn and .dzn into {@code dir}; returns the io.json. */
    public static Path copy(String model, Path dir) throws IOException {
        for (String ext : List.of(".io.json", ".mzn", ".dzn")) {
            try (InputStream in = open("models/" + model + ext)) {
                Files.copy(in, dir.resolve(model + ext), StandardCopyOption.REPLACE_EXISTING);
            }
        }
        return dir.resolve(model + ".io.json");
    }

    /** The text of roqme/FILE, e.g. {@code roqme("worked.roqme.json")}. */
    public static String roqme(String file) throws IOException {
        try (InputStream in = open("roqme/" + file)) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
    }

    /** Copies roqme/FILE into {@code dir}; returns the copy. */
    public static Path copyRoqme(String file, Path dir) throws IOException {
        try (InputStream in = open("roqme/" + file)) {
            Files.copy(in, dir.resolve(file), StandardCopyOption.REPLACE_EXISTING);
        }
        return dir.resolve(file);
    }

    private static InputStream open(String resource) {
        InputStream in = TestModels.class.getResourceAsStream(resource);
        if (in == null) {
            throw new IllegalArgumentException("no test model " + resource + " in the runtime test kit");
        }
        return in;
    }
}
