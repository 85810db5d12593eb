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
        Toolchain toolchain = new Toolchain();
        assertEquals(toolchain.messages(), 0, toolchain.generate(Toolchain.ROOT.resolve("examples/hospital-delivery/hospital.miron").toString(), out.toString()));
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

    /**
     * sounds is a boolean varpoint: io.json lists its values as false/true (the .mzn decides the
     * index 0/1 into them); dayShift turns it on, nightShift off.
     */
    @Test
    public void soundsIsTrueByDayAndFalseAtNight() {
        assertEquals("boolean", mzn.varpoint("sounds").get("kind").asText());
        assertEquals("[false,true]", mzn.varpoint("sounds").get("values").toString());
        ObjectNode data = mzn.defaults();
        data.put("context_Hospital_shift_known", true);
        data.put("context_Hospital_urgent_known", true);
        data.put("context_Hospital_shift", 0); // day (day, evening, night)
        assertEquals("true", mzn.value("sounds", mzn.solve(data)));
        data.put("context_Hospital_shift", 2);
        assertEquals("false", mzn.value("sounds", mzn.solve(data)));
    }

    /**
     * The rules never contradict each other: with every context known and at every combination
     * of the contexts and of metric values on both sides of the rules' thresholds, there is a
     * decision (an UNSAT model would leave the robot on its last configuration).
     */
    @Test
    public void theRulesAgreeInEverySituation() {
        int situations = 0;
        for (int crowding = 0; crowding < 3; crowding++) {
            for (int shift = 0; shift < 3; shift += 2) { // day, night
                for (boolean urgent : new boolean[] { false, true }) {
                    for (boolean lowBattery : new boolean[] { false, true }) {
                        for (double safety : new double[] { 0.3, 0.9 }) {
                            for (double comfort : new double[] { 0.3, 0.9 }) {
                                for (double autonomy : new double[] { 0.2, 0.9 }) {
                                    ObjectNode data = mzn.defaults();
                                    data.put("context_Hospital_crowding", crowding);
                                    data.put("context_Hospital_shift", shift);
                                    data.put("context_Hospital_urgent", urgent);
                                    data.put("context_Hospital_lowBattery", lowBattery);
                                    for (String context : new String[] { "crowding", "shift", "urgent", "lowBattery" }) {
                                        data.put("context_Hospital_" + context + "_known", true);
                                    }
                                    data.put("metric_Hospital_safety", safety);
                                    data.put("metric_Hospital_timeliness", 0.1);
                                    data.put("metric_Hospital_comfort", comfort);
                                    data.put("metric_Hospital_autonomy", autonomy);
                                    mzn.solve(data); // fails the test when unsatisfiable
                                    situations++;
                                }
                            }
                        }
                    }
                }
            }
        }
        assertEquals(192, situations);
    }
}
