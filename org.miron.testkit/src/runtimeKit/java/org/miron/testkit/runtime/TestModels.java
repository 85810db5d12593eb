package org.miron.testkit.runtime;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.List;

/**
 * The runtime's small test models (beside this class in models/): testbot, whose rules
 * {@link TestbotRules} also states in Java, and portbot. Copied into a folder a test owns, so it may
 * change or corrupt them.
 */
public final class TestModels {
    private TestModels() {
    }

    /** Copies the model's .io.json, .mzn and .dzn into {@code dir}; returns the io.json. */
    public static Path copy(String model, Path dir) throws IOException {
        for (String ext : List.of(".io.json", ".mzn", ".dzn")) {
            try (InputStream in = TestModels.class.getResourceAsStream("models/" + model + ext)) {
                if (in == null) {
                    throw new IllegalArgumentException("no test model " + model + ext + " in the runtime test kit");
                }
                Files.copy(in, dir.resolve(model + ext), StandardCopyOption.REPLACE_EXISTING);
            }
        }
        return dir.resolve(model + ".io.json");
    }
}
