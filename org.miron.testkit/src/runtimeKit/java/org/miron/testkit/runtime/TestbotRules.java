package org.miron.testkit.runtime;

import java.util.Map;
import org.miron.runtime.engine.SolveResult;
import org.miron.runtime.engine.SolverBackend;

/**
 * The testbot model's rules in Java (models/testbot.mzn beside TestModels): task = dock when power_autonomy < 0.3 or
 * a known battery is below 5, else pickDeliverCharge; maxVelocity the highest value allowed by
 * safety (and by a known LOW space). Solves in microseconds, so the engine's first decision
 * comes out as fast as the machine allows: the races of issue 10 show up every time.
 */
public final class TestbotRules implements SolverBackend {
    @Override
    public String name() {
        return "testbot-rules";
    }

    @Override
    public void check() {
    }

    @Override
    public SolveResult solve(Map<String, Object> p) {
        boolean batteryKnown = (Boolean) p.get("context_Intralogistics_BatteryLevel_known");
        double battery = ((Number) p.get("context_Intralogistics_BatteryLevel")).doubleValue();
        boolean dock = ((Number) p.get("metric_Intralogistics_power_autonomy")).doubleValue() < 0.3
                || (batteryKnown && battery < 5.0);
        int task = (Boolean) p.get("task_input") ? (Integer) p.get("task_input_value") : dock ? 2 : 3;
        int velocity = 10 + (int) Math.floor(90.0 * ((Number) p.get("metric_Intralogistics_safety")).doubleValue());
        if ((Boolean) p.get("context_Intralogistics_Space_known") && (Integer) p.get("context_Intralogistics_Space") == 0) {
            velocity = Math.min(velocity, 30);
        }
        int maxVelocity = (Boolean) p.get("maxVelocity_input") ? (Integer) p.get("maxVelocity_input_value") : velocity - 10;
        return new SolveResult(SolveResult.Status.SOLVED, Map.of("task_var", task, "maxVelocity_var", maxVelocity), true,
                null, 0);
    }
}
