package org.miron.runtime.roqme;

import com.fasterxml.jackson.databind.node.ObjectNode;
import org.miron.runtime.roqme.model.RoqmeModel;

/**
 * The {@code actions} of a {@code roqme.observation} message (docs/wire-formats.md), written alike
 * by the live provider and the simulator's timeline: what a fired observation does to the beliefs,
 * variables and timers, with MEDIUM for a strength the model leaves out.
 */
public final class ObservationMessage {
    private ObservationMessage() {
    }

    public static void putActions(ObjectNode message, RoqmeModel.Observation observation) {
        var actions = message.putArray("actions");
        for (RoqmeModel.Action a : observation.actions()) {
            ObjectNode x = actions.addObject();
            x.put("kind", a.kind());
            switch (a.kind()) {
                case "reinforces", "undermines" -> {
                    x.put("belief", a.belief());
                    x.put("strength", a.strength() == null ? "MEDIUM" : a.strength());
                }
                case "clears" -> x.put("belief", a.belief());
                case "sets" -> x.put("var", a.var());
                default -> x.put("timer", a.timer());
            }
        }
    }
}
