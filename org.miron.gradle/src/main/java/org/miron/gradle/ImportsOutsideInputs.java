package org.miron.gradle;

import java.io.File;
import java.nio.file.Path;
import java.util.Collection;
import java.util.Set;

import org.gradle.api.logging.Logger;

/**
 * A model may import a file outside its model folders (`import "../../common/robot.bt"`): it is
 * generated from, but Gradle does not see it change, so the user is told to add its folder to
 * `miron.models` rather than be surprised by an UP-TO-DATE task.
 */
final class ImportsOutsideInputs {
    private ImportsOutsideInputs() {
    }

    /** Names the file as diagnostics do: relative to the root project's folder when inside it. */
    static void warn(Logger logger, Collection<File> loaded, Set<File> inputs, File rootDir) {
        Path root = rootDir.toPath().toAbsolutePath().normalize();
        for (File file : loaded) {
            if (!inputs.contains(file.getAbsoluteFile())) {
                Path path = file.toPath().toAbsolutePath().normalize();
                logger.warn("{}: warning: imported from outside the model folders; Gradle will not re-run "
                        + "generateMiron when it changes: add its folder to miron.models",
                        path.startsWith(root) ? root.relativize(path) : path);
            }
        }
    }
}
