package org.miron.generator;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Map;

import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

import com.fasterxml.jackson.databind.node.ObjectNode;

/** The hospital example: rules over contexts apply only once the contexts are known. */
public class HospitalDecisionTest {
    @ClassRule
    public static TemporaryFolder temp = new TemporaryFolder();

    private static MiniZinc mzn;

    @BeforeClass
    public static void generate() throws IOException {
        Path out = temp.newFolder("out").toPath();
        Cli cli = new Cli();
        assertEquals(cli.out(), 0, cli.run("generate",
                Cli.ROOT.resolve("examples/hospital-delivery/hospital.miron").toString(), "-o", out.toString()));
        mzn = new MiniZinc(out.resolve("hospital.io.json"));
    }

    /** Safe but late: the objective wants to drive fast. */
    private static ObjectNode hurried() {
        ObjectNode data = mzn.defaults();
        data.put("metric_Hospital_safety", 0.9);
        data.put("metric_Hospital_timeliness", 0.1);
        data.put("metric_Hospital_comfort", 0.8);
        data.put("metric_Hospital_autonomy", 0.9);
        data.put("context_Hospital_crowding", 2); // Crowding::DENSE (EMPTY, LIGHT, DENSE)
        return data;
    }

    private static double speed(Map<String, Integer> d) {
        return Double.parseDouble(mzn.value("driveSpeed", d));
    }

    @Test
    public void anUnknownContextKeepsItsRulesInactive() {
        assertEquals(1.0, speed(mzn.solve(hurried())), 1e-9);
    }

    @Test
    public void aKnownContextFiresItsRule() {
        ObjectNode data = hurried();
        data.put("context_Hospital_crowding_known", true);
        Map<String, Integer> d = mzn.solve(data);
        assertTrue("crowded corridor: drive at most 0.3, got " + speed(d), speed(d) <= 0.3 + 1e-9);
        assertEquals("careful", mzn.value("navigation", d));
    }

    @Test
    public void lowAutonomyChargesFirstUnlessOverridden() {
        ObjectNode data = hurried();
        data.put("metric_Hospital_autonomy", 0.2);
        data.put("context_Hospital_lowBattery_known", true);
        assertEquals("charge", mzn.value("preparation", mzn.solve(data)));
        data.put("preparation_input", true);
        data.put("preparation_input_value", mzn.index("preparation", "none"));
        assertEquals("none", mzn.value("preparation", mzn.solve(data)));
    }
}
