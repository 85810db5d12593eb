package org.miron.dsl.tests;

import static org.junit.Assert.assertEquals;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.xtext.diagnostics.Severity;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * A large model (thousands of references across two files) loads and validates without errors.
 * How long it takes is measured by {@code gradle :org.miron.dsl:benchmark} ({@link ScaleBenchmark}),
 * not asserted here.
 */
public class ScaleTest {

    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    @Test
    public void largeModel() throws IOException {
        File main = write(folder.getRoot(), 1500);
        List<String> errors = Models.validateAll(Models.load(main)).stream().filter(i -> i.getSeverity() == Severity.ERROR)
                .map(Models::format).limit(5).collect(Collectors.toList());
        assertEquals(List.of(), errors);
    }

    /** Writes big.roqme and big.miron with n contexts, properties, observations and rules; returns big.miron. */
    static File write(File dir, int n) throws IOException {
        StringBuilder roqme = new StringBuilder("roqme Big\ntype Level : enum { LOW, MID, HIGH }\n");
        for (int i = 0; i < n; i++) {
            roqme.append("context c").append(i).append(" : number (0:100)\n");
            roqme.append("context l").append(i).append(" : Level\n");
            roqme.append("property p").append(i).append('\n');
            roqme.append("observation o").append(i).append(" : c").append(i).append(" > 50 & l").append(i)
                    .append(" = Level::HIGH reinforces p").append(i).append(" high\n");
        }
        File big = new File(dir, "big.roqme");
        Files.writeString(big.toPath(), roqme, StandardCharsets.UTF_8);
        StringBuilder miron = new StringBuilder("import \"big.roqme\" as b\n");
        miron.append("@varpoint v : number (0:1:100)\n");
        for (int i = 0; i < n; i++) {
            miron.append("rule r").append(i).append(" : b.c").append(i).append(" < 10 & b.l").append(i)
                    .append(" = b::Level::LOW implies v <= ").append(i % 100).append('\n');
        }
        File main = new File(dir, "big.miron");
        Files.writeString(main.toPath(), miron, StandardCharsets.UTF_8);
        return main;
    }
}
