package org.miron.cli;

import java.io.IOException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Map;
import org.miron.runtime.roqme.model.RoqmeModel;
import org.miron.runtime.sim.LiveWorld;
import org.miron.runtime.sim.Setup;
import org.miron.runtime.sim.WorldException;
import org.miron.runtime.sim.WorldModel;
import org.miron.runtime.sim.WorldReader;

/**
 * A world file checked against a generated model (its woven tree's skills, its RoQME contexts) and
 * made live for the mock skill interface: what `miron demo` and `miron skill-mock --world` run.
 */
final class ModelWorld {
    private ModelWorld() {
    }

    /** Reads and checks the world (problems: WorldException) and wraps it for the mock, contexts in the model's namespaces. */
    static LiveWorld live(Path worldFile, Path tree, RoqmeModel roqme, long seed, double timeScale, String busIn)
            throws WorldException, IOException {
        WorldModel world = WorldReader.read(worldFile, Setup.env(tree, roqme));
        Map<String, String> namespaces = new LinkedHashMap<>();
        for (RoqmeModel.Variable v : roqme.contexts()) {
            namespaces.put(v.name(), v.namespace());
        }
        return new LiveWorld(world, seed, timeScale, namespaces, busIn);
    }
}
