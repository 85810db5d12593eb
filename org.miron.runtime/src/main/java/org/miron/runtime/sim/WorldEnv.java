package org.miron.runtime.sim;

import java.util.Map;
import java.util.Set;
import org.miron.runtime.roqme.model.RoqmeModel;

/**
 * What a world file is checked against: the skills the behaviour tree pushes (with the ports each
 * is given) and the RoQME contexts the model receives (not the derived ones), by name.
 */
public record WorldEnv(Map<String, Set<String>> skills, Map<String, RoqmeModel.Type> contexts) {
}
