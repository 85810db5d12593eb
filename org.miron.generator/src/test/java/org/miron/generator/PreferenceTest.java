package org.miron.generator;

import static org.junit.Assert.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * Models without impacts only satisfy their rules, yet still prefer the preset and then the
 * current value; and the sampled utility tables interpolate as docs/generators.md says.
 */
public class PreferenceTest {
    @ClassRule
    public static TemporaryFolder temp = new TemporaryFolder();

    private static Path out;

    @BeforeClass
    public static void generate() throws IOException {
        Path models = Toolchain.copyResources("weaving", temp.newFolder("models").toPath());
        Files.writeString(models.resolve("sampled.miron"), "import \"nominal.bt\" as bt\n\n"
                + "property safety\nproperty speed\n\n"
                + "@varpoint v : number (0:1:10) { 2 affects safety+++, 6 affects { safety---, speed++ } }\n");
        out = temp.newFolder("out").toPath();
        for (String model : new String[] { "in_middle", "port", "sampled", "split" }) {
            Toolchain toolchain = new Toolchain();
            assertEquals(toolchain.messages(), 0, toolchain.generate(models.resolve(model + ".miron").toString(), out.toString()));
        }
    }

    @Test
    public void withoutImpactsThePresetIsPreferred() throws IOException {
        MiniZinc mzn = new MiniZinc(out.resolve("in_middle.io.json"));
        assertEquals("solve satisfy", true, Files.readString(out.resolve("in_middle.mzn")).contains(") satisfy;"));
        ObjectNode data = mzn.defaults();
        assertEquals("nominal", mzn.value("v", mzn.solve(data)));
        data.put("v_current", mzn.index("v", "b"));
        assertEquals("nominal", mzn.value("v", mzn.solve(data)));
        data.put("v_input", true);
        data.put("v_input_value", mzn.index("v", "a"));
        assertEquals("a", mzn.value("v", mzn.solve(data)));
    }

    @Test
    public void withoutImpactsOrPresetTheCurrentValueIsKept() {
        MiniZinc mzn = new MiniZinc(out.resolve("port.io.json"));
        ObjectNode data = mzn.defaults();
        assertEquals("0.1", mzn.value("speed", mzn.solve(data)));
        data.put("speed_current", mzn.index("speed", "0.7"));
        assertEquals("0.7", mzn.value("speed", mzn.solve(data)));
    }

    @Test
    public void utilitiesInterpolateBetweenSamplesAndFallBackToNeutral() throws IOException {
        String dzn = Files.readString(out.resolve("sampled.dzn"));
        // safety: neutral 50 at 0, +++ = 100 at 2, --- = 0 at 6, back to neutral 50 at 10.
        assertEquals("v_y_safety = array1d(0..10, [\n  50.0, 75.0, 100.0, 75.0, 50.0, 25.0, 0.0, 12.5, 25.0, 37.5,\n  50.0]);",
                line(dzn, "v_y_safety"));
        // speed: the sample at 2 has no impact on speed (neutral), ++ = 500/6 at 6.
        assertEquals("v_y_speed = array1d(0..10, [\n  50.0, 50.0, 50.0, 58.333333, 66.666667, 75.0, 83.333333, 75.0, 66.666667, 58.333333,\n  50.0]);",
                line(dzn, "v_y_speed"));
    }

    @Test
    public void varpointsOfImportedMironModelsAreGeneratedToo() throws IOException {
        MiniZinc mzn = new MiniZinc(out.resolve("split.io.json"));
        assertEquals("nominal", mzn.value("v", mzn.solve(mzn.defaults())));
        String tree = Files.readString(out.resolve("split.ext.xml"));
        assertEquals(tree, true, tree.contains("<Switch2 variable=\"{v_sel}\" case_1=\"a\" case_2=\"b\">"));
    }

    private static String line(String text, String name) {
        int start = text.indexOf(name + " = ");
        return text.substring(start, text.indexOf(";", start) + 1);
    }
}
