package org.miron.dsl.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.List;
import java.util.stream.Collectors;

import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.xtext.diagnostics.Severity;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/** A large model (thousands of references) validates in reasonable time: no quadratic blow-up. */
public class ScaleTest {

    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    @Test
    public void largeModel() throws IOException {
        int n = 1500;
        StringBuilder roqme = new StringBuilder("roqme Big\ntype Level : enum { LOW, MID, HIGH }\n");
        for (int i = 0; i < n; i++) {
            roqme.append("context c").append(i).append(" : number (0:100)\n");
            roqme.append("context l").append(i).append(" : Level\n");
            roqme.append("property p").append(i).append('\n');
            roqme.append("observation o").append(i).append(" : c").append(i).append(" > 50 & l").append(i)
                    .append(" = Level::HIGH reinforces p").append(i).append(" high\n");
        }
        File big = folder.newFile("big.roqme");
        Files.writeString(big.toPath(), roqme, StandardCharsets.UTF_8);
        StringBuilder miron = new StringBuilder("import \"big.roqme\" as b\n");
        miron.append("@varpoint v : number (0:1:100)\n");
        for (int i = 0; i < n; i++) {
            miron.append("rule r").append(i).append(" : b.c").append(i).append(" < 10 & b.l").append(i)
                    .append(" = b::Level::LOW implies v <= ").append(i % 100).append('\n');
        }
        File main = folder.newFile("big.miron");
        Files.writeString(main.toPath(), miron, StandardCharsets.UTF_8);
        long start = System.nanoTime();
        Resource resource = Models.load(main);
        List<String> errors = Models.validateAll(resource).stream().filter(i -> i.getSeverity() == Severity.ERROR)
                .map(Models::format).limit(5).collect(Collectors.toList());
        long seconds = (System.nanoTime() - start) / 1_000_000_000L;
        assertEquals(List.of(), errors);
        assertTrue("took " + seconds + " s", seconds < 60);
        System.out.println("ScaleTest: " + (6 * n) + " elements loaded and validated in " + seconds + " s");
    }
}
