package org.miron.cli;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertNotNull;
import static org.junit.Assert.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.runtime.roqme.model.RoqmeModel;
import org.miron.runtime.sim.Coverage;
import org.miron.runtime.sim.Policy;
import org.miron.runtime.sim.Simulation;
import org.miron.runtime.sim.TimelineEvent;

/**
 * Issue 40: a simulated shift of each example exercises its whole model. Every RoQME metric moves
 * under both policies (its estimate spans more than 0.05: a metric whose observations never fire
 * stays at its reference), and under the adaptive policy every rule applies at least once.
 */
public class ExamplesExercisedTest {
    private static final long SHIFT_MS = 8 * 3_600_000L;

    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    @Test
    public void intralogistics() throws Exception {
        exercised("examples/intralogistics/intralogistics.miron", "examples/intralogistics/world.json");
    }

    @Test
    public void hospital() throws Exception {
        exercised("examples/hospital-delivery/hospital.miron", "examples/hospital-delivery/world.json");
    }

    private void exercised(String model, String world) throws Exception {
        StringWriter err = new StringWriter();
        List<Policy> policies = List.of(Policy.parse("adaptive"), Policy.parse("preset"));
        SimulationModel.Loaded loaded = SimulationModel.load(Cli.ROOT.resolve(model), Cli.ROOT.resolve(world),
                temp.getRoot().toPath(), policies, new PrintWriter(err), "simulate", 1);
        assertNotNull(err.toString(), loaded.setup());
        List<String> metrics = loaded.setup().roqme().beliefs().stream().filter(RoqmeModel.Belief::isProperty)
                .map(RoqmeModel.Belief::name).toList();
        List<String> flat = new ArrayList<>();
        for (Policy policy : policies) {
            Simulation.Result r = new Simulation(loaded.setup(), policy, 1, SHIFT_MS, SHIFT_MS).run();
            Map<String, double[]> span = new HashMap<>();
            for (TimelineEvent e : r.timeline()) {
                if (e.topic().equals("roqme.estimate")) {
                    double v = e.body().path("value").asDouble();
                    double[] s = span.computeIfAbsent(e.body().path("name").asText(), k -> new double[] { v, v });
                    s[0] = Math.min(s[0], v);
                    s[1] = Math.max(s[1], v);
                }
            }
            for (String m : metrics) {
                double[] s = span.get(m);
                if (s == null || s[1] - s[0] < 0.05) {
                    flat.add(policy.name() + ": " + m + (s == null ? " never moved" : " within [" + s[0] + ", " + s[1] + "]"));
                }
            }
            if (policy.adaptive()) {
                Coverage c = r.coverage();
                List<String> never = new ArrayList<>();
                for (int i = 0; i < c.rules().size(); i++) {
                    if (c.applied(i) == 0) {
                        never.add(c.rules().get(i));
                    }
                }
                assertTrue(model + ": rules never applied under adaptive: " + never, never.isEmpty());
                assertTrue(model + " has rules", c.rules().size() > 0);
            }
        }
        assertEquals(model + ": metrics that did not move in a shift", List.of(), flat);
    }
}
