package org.miron.gradle;

import org.gradle.api.Project;
import org.gradle.api.file.ConfigurableFileCollection;

/**
 * The `miron { }` block of a user's build: which models to generate and the options of
 * `miron generate` (`--bt-format`, `--weights`). The tasks read it when they run, so the block
 * may come anywhere after `apply plugin`.
 */
public class MironExtension {
    private final ConfigurableFileCollection models;
    private Integer btFormat;
    private String weights = "need";

    public MironExtension(Project project) {
        models = project.files(project.fileTree("src/main/miron").include("**/*.miron"));
    }

    /** The MIRoN models to generate; by default every .miron under src/main/miron. */
    public ConfigurableFileCollection getModels() {
        return models;
    }

    /** Replaces the models: files, folders (every .miron below them) or file trees, as project.files takes. */
    public void setModels(Object... paths) {
        models.setFrom(paths);
    }

    /** BehaviorTree.CPP format of the woven trees, 3 or 4; null (the default): that of the imported tree. */
    public Integer getBtFormat() {
        return btFormat;
    }

    public void setBtFormat(Integer btFormat) {
        this.btFormat = btFormat;
    }

    /** Objective weights: need (the default) or metric, as `miron generate --weights`. */
    public String getWeights() {
        return weights;
    }

    public void setWeights(String weights) {
        this.weights = weights;
    }
}
