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

/**
 * The intralogistics example's MiniZinc model, solved by the real minizinc (Gecode), gives the
 * decisions a human expects: dock on low autonomy, slow down when safety is low, stay on the
 * nominal behaviour when nothing is wrong, keep the current value when nothing changed, and let
 * a manual override win over the rules.
 */
public class IntralogisticsDecisionTest {
    @ClassRule
    public static TemporaryFolder temp = new TemporaryFolder();

    private static MiniZinc need;
    private static MiniZinc metric;

    @BeforeClass
    public static void generate() throws IOException {
        need = generate("need");
        metric = generate("metric");
    }

    private static MiniZinc generate(String weights) throws IOException {
        Path out = temp.newFolder(weights).toPath();
        Toolchain toolchain = new Toolchain();
        int exit = toolchain.generate(Toolchain.ROOT.resolve("examples/intralogistics/intralogistics.miron").toString(),
                out.toString(), WeightPolicy.of(weights));
        assertEquals(toolchain.messages(), 0, exit);
        return new MiniZinc(out.resolve("intralogistics.io.json"));
    }

    private static ObjectNode metrics(MiniZinc mzn, double safety, double missionCompletion, double powerAutonomy) {
        ObjectNode data = mzn.defaults();
        data.put("metric_Intralogistics_safety", safety);
        data.put("metric_Intralogistics_mission_completion", missionCompletion);
        data.put("metric_Intralogistics_power_autonomy", powerAutonomy);
        return data;
    }

    private static double velocity(Map<String, Integer> decisions) {
        return Double.parseDouble(need.value("maxVelocity", decisions));
    }

    @Test
    public void lowPowerAutonomyDocks() {
        Map<String, Integer> d = need.solve(metrics(need, 0.7, 0.5, 0.2));
        assertEquals("dock", need.value("task", d));
    }

    @Test
    public void powerAutonomyAboveTheThresholdKeepsThePreset() {
        Map<String, Integer> d = need.solve(metrics(need, 0.7, 0.5, 0.35));
        assertEquals("pickDeliverCharge", need.value("task", d));
    }

    @Test
    public void nothingWrongKeepsThePreset() {
        Map<String, Integer> d = need.solve(need.defaults());
        assertEquals("pickDeliverCharge", need.value("task", d));
    }

    @Test
    public void lowSafetySlowsDown() {
        Map<String, Integer> d = need.solve(metrics(need, 0.1, 0.6, 0.5));
        assertEquals(10.0, velocity(d), 2.0);
    }

    @Test
    public void lowMissionCompletionSpeedsUpWhenSafetyIsFine() {
        Map<String, Integer> d = need.solve(metrics(need, 0.9, 0.2, 0.5));
        assertEquals(100.0, velocity(d), 2.0);
    }

    @Test
    public void metricWeightsFavourTheBestFulfilledProperty() {
        // Same situation as lowSafetySlowsDown: with weight = metric, mission completion wins.
        Map<String, Integer> d = metric.solve(metrics(metric, 0.1, 0.6, 0.5));
        assertEquals(100.0, Double.parseDouble(metric.value("maxVelocity", d)), 2.0);
    }

    @Test
    public void theCurrentDecisionIsKeptWhenNothingChanged() {
        ObjectNode data = metrics(need, 0.3, 0.6, 0.5);
        Map<String, Integer> first = need.solve(data);
        data.put("task_current", first.get("task_var"));
        data.put("maxVelocity_current", first.get("maxVelocity_var"));
        assertEquals(first, need.solve(data));
    }

    @Test
    public void tiesKeepTheCurrentValueInsteadOfFlapping() {
        // Equal needs: every velocity has the same weighted utility, so only the tie-break decides.
        for (String current : new String[] { "40", "73" }) {
            ObjectNode data = metrics(need, 0.5, 0.5, 0.5);
            data.put("maxVelocity_current", need.index("maxVelocity", current));
            Map<String, Integer> d = need.solve(data);
            assertEquals(Double.parseDouble(current), velocity(d), 1e-9);
        }
    }

    @Test
    public void theTieBreakNeverOutweighsARealGain() {
        // Slightly more need for safety: from 11 to 10 the weighted utility grows by 0.0185 only,
        // yet the current value must give way.
        ObjectNode data = metrics(need, 0.45, 0.5, 0.5);
        data.put("maxVelocity_current", need.index("maxVelocity", "11"));
        assertEquals(10.0, velocity(need.solve(data)), 1e-9);
    }

    @Test
    public void thePresetWinsOverTheCurrentValueOnceTheRuleNoLongerHolds() {
        ObjectNode data = metrics(need, 0.7, 0.5, 0.8);
        data.put("task_current", need.index("task", "dock"));
        assertEquals("pickDeliverCharge", need.value("task", need.solve(data)));
    }

    @Test
    public void aManualOverrideWinsOverTheRules() {
        ObjectNode data = metrics(need, 0.7, 0.5, 0.1);
        data.put("task_input", true);
        data.put("task_input_value", need.index("task", "pick"));
        data.put("maxVelocity_input", true);
        data.put("maxVelocity_input_value", need.index("maxVelocity", "55"));
        Map<String, Integer> d = need.solve(data);
        assertEquals("pick", need.value("task", d));
        assertEquals(55.0, velocity(d), 1e-9);
    }

    @Test
    public void decisionsAreInsideTheirTables() {
        Map<String, Integer> d = need.solve(need.defaults());
        assertEquals(2, d.size());
        assertTrue(d.get("task_var") >= 0 && d.get("task_var") < 4);
        assertTrue(d.get("maxVelocity_var") >= 0 && d.get("maxVelocity_var") < 91);
    }
}
