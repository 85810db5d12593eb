package org.miron.gradle;

import java.io.File;
import java.util.Set;
import java.util.TreeSet;

import org.gradle.api.Project;
import org.gradle.api.file.FileCollection;
import org.gradle.api.file.FileTree;

/**
 * What the tasks read: the models, and every file of the MIRoN languages in the model folders,
 * which is where a model's imports are. A model folder is the root of the file tree a model came
 * from (src/main/miron for the default), the folder given, or a model file's own folder.
 */
final class ModelSources {
    /** The extensions ModelLoader reads: trees (.bt, BehaviorTree.CPP .xml), RoQME, MIRoN. */
    static final String[] PATTERNS = { "**/*.bt", "**/*.xml", "**/*.roqme", "**/*.miron" };

    private ModelSources() {
    }

    /** The .miron files among models: a folder given stands for the .miron files below it. */
    static FileTree models(FileCollection models) {
        return models.getAsFileTree().matching(p -> p.include("**/*.miron"));
    }

    /** Every model-language file below the model folders, resolved when Gradle asks. */
    static FileTree sources(Project project, FileCollection models) {
        return project.files((java.util.concurrent.Callable<Set<File>>) () -> folders(models))
                .getAsFileTree().matching(p -> p.include(PATTERNS));
    }

    /** The roots of the trees the models come from: each file less its path relative to its tree. */
    static Set<File> folders(FileCollection models) {
        Set<File> roots = new TreeSet<>();
        models.getAsFileTree().visit(details -> {
            if (!details.isDirectory()) {
                File root = details.getFile();
                for (int i = 0; i < details.getRelativePath().getSegments().length; i++) {
                    root = root.getParentFile();
                }
                roots.add(root);
            }
        });
        return roots;
    }
}
