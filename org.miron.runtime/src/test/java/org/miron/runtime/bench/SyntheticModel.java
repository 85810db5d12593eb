package org.miron.runtime.bench;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.resource.Resource;
import org.miron.generator.WeightPolicy;
import org.miron.generator.standalone.BatchGeneration;
import org.miron.generator.standalone.ModelLoader;

/**
 * A generated model of any size for scale tests and the bench: N numeric varpoints of 100 values
 * (0..99) with impacts on two of four properties, and 4 rules per varpoint (metric p_k below
 * 0.(k+2) caps the varpoint at 90 - 10 k). With every metric 0 all rules fire: each varpoint is
 * capped at 60, and its best value is 10 (p_a++ there, weight 1 on everything).
 */
public final class SyntheticModel {
    private static final String TREE = """
            <root main_tree_to_execute="Main">
              <BehaviorTree ID="Main">
                <Action ID="A" name="only"/>
              </BehaviorTree>
            </root>
            """;

    private SyntheticModel() {
    }

    /**
     * Name of varpoint i: long, as real names are, so that the parameters of 1 000 varpoints pass
     * Linux's 128 KiB limit on one command-line argument.
     */
    public static String varpoint(int i) {
        return "navigationSpeedLimitOfTheWarehouseRobot" + i;
    }

    /** The MIRoN text of an n-varpoint model. */
    public static String text(int n) {
        StringBuilder b = new StringBuilder("import \"nominal.bt\" as bt\n\n");
        for (int k = 0; k < 4; k++) {
            b.append("property p").append(k).append('\n');
        }
        for (int i = 0; i < n; i++) {
            b.append("@varpoint ").append(varpoint(i)).append(" : number (0:1:99) { 10 affects p").append(i % 4)
                    .append("++, 90 affects { p").append((i + 1) % 4).append("+, p").append(i % 4).append("- } }\n");
        }
        for (int i = 0; i < n; i++) {
            for (int k = 0; k < 4; k++) {
                b.append("rule r").append(i).append('_').append(k).append(" : p").append(k).append(" < 0.")
                        .append(k + 2).append(" implies ").append(varpoint(i)).append(" <= ").append(90 - 10 * k).append('\n');
            }
        }
        return b.toString();
    }

    /**
     * {@code gradle :org.miron.runtime:syntheticModel -Pvarpoints=N -Pdir=DIR}: writes and generates
     * the N-varpoint model in DIR (to time {@code miron generate DIR/src/synN.miron} on it).
     */
    public static void main(String[] args) throws IOException {
        int n = Integer.parseInt(args[0]);
        System.out.println("generated " + generate(n, Path.of(args[1])));
    }

    /** Writes syn&lt;n&gt;.miron into dir/src and generates it into dir/out; returns the io.json. */
    public static Path generate(int n, Path dir) throws IOException {
        Path src = Files.createDirectories(dir.resolve("src"));
        Path out = Files.createDirectories(dir.resolve("out"));
        Files.writeString(src.resolve("nominal.bt"), TREE);
        Path miron = src.resolve("syn" + n + ".miron");
        Files.writeString(miron, text(n));
        ModelLoader loader = new ModelLoader();
        List<Resource> resources = new ArrayList<>(List.of(loader.load(new File(miron.toString()))));
        BatchGeneration.Outcome outcome = new BatchGeneration(loader, WeightPolicy.NEED)
                .run(resources, BatchGeneration.folder(out));
        if (!outcome.succeeded()) {
            throw new IOException("synthetic model " + n + " did not generate: " + outcome.validation()
                    + outcome.generationErrors() + " " + outcome.writeError());
        }
        return out.resolve("syn" + n + ".io.json");
    }
}
