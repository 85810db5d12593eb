package org.miron.cli.demo;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.engine.InputSpec;
import org.miron.runtime.engine.IoModel;
import org.miron.runtime.player.Scenario;
import org.miron.runtime.roqme.model.RoqmeModel;

/**
 * Whether a scenario fits the model it is played against: every context it publishes is one the
 * provider reads (a context of the model's RoQME part that is not derived) or one the engine reads
 * (an io.json input), and every estimate a metric of the model. A scenario written for another
 * model would otherwise play silently while the engine decides on its defaults.
 */
public final class ScenarioInputs {
    private ScenarioInputs() {
    }

    /**
     * One line per input the model does not know, e.g. {@code scenario.json: power_autonomy
     * (Intralogistics) is not an input of hospital.miron}; empty when the scenario fits.
     *
     * @param roqme the model's RoQME part (null: none)
     */
    public static List<String> unknown(Scenario scenario, String scenarioName, IoModel io, RoqmeModel roqme,
            String modelName) {
        Set<String> contexts = new LinkedHashSet<>();
        Set<String> metrics = new LinkedHashSet<>();
        for (InputSpec in : io.inputs()) {
            (in.isMetric() ? metrics : contexts).add(key(in.name(), in.namespace()));
        }
        if (roqme != null) {
            roqme.contexts().stream().filter(c -> c.derived() == null || c.derived().isNull())
                    .forEach(c -> contexts.add(key(c.name(), c.namespace())));
            roqme.beliefs().stream().filter(RoqmeModel.Belief::isProperty)
                    .forEach(b -> metrics.add(key(b.name(), b.namespace())));
        }
        Set<String> problems = new LinkedHashSet<>();
        for (Scenario.Step step : scenario.steps()) {
            String name = step.body().path("name").asText();
            String namespace = step.body().path("namespace").asText("");
            boolean estimate = step.topic().equals(Topics.ESTIMATE);
            Set<String> known = estimate ? metrics : contexts;
            if (!known.contains(key(name, namespace)) && !(namespace.isEmpty() && knownByName(known, name))) {
                problems.add(scenarioName + ": " + name + (namespace.isEmpty() ? "" : " (" + namespace + ")")
                        + " is not an input of " + modelName);
            }
        }
        return new ArrayList<>(problems);
    }

    private static boolean knownByName(Set<String> known, String name) {
        return known.stream().anyMatch(k -> k.startsWith(name + "\0"));
    }

    private static String key(String name, String namespace) {
        return name + "\0" + (namespace == null ? "" : namespace);
    }
}
