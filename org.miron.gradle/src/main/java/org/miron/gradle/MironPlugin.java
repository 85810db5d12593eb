package org.miron.gradle;

import java.io.File;

import org.gradle.api.Plugin;
import org.gradle.api.Project;
import org.gradle.api.plugins.BasePlugin;
import org.gradle.api.plugins.JavaPlugin;
import org.gradle.api.tasks.SourceSet;
import org.gradle.api.tasks.SourceSetContainer;
import org.gradle.language.base.plugins.LifecycleBasePlugin;

/**
 * `org.miron.generate`: checks and generates a project's MIRoN models as part of its build
 * (docs/gradle.md). The `miron { }` extension says which models; `checkMiron` runs with `check`;
 * `generateMiron` writes into build/generated/miron, a resource folder of the main source set with
 * the java plugin (so the jar holds the artefacts), else built by `assemble`.
 */
public class MironPlugin implements Plugin<Project> {
    public static final String CHECK_TASK = "checkMiron";
    public static final String GENERATE_TASK = "generateMiron";

    @Override
    public void apply(Project project) {
        project.getPluginManager().apply(BasePlugin.class);
        MironExtension extension = project.getExtensions().create("miron", MironExtension.class, project);
        File buildDir = project.getLayout().getBuildDirectory().get().getAsFile();

        MironCheck check = project.getTasks().create(CHECK_TASK, MironCheck.class, task -> {
            task.setGroup(LifecycleBasePlugin.VERIFICATION_GROUP);
            task.setDescription("Checks the MIRoN models' folders: every .bt, .xml, .roqme and .miron file.");
            task.setModels(extension.getModels());
            task.setReport(new File(buildDir, "reports/miron/check.txt"));
        });
        project.getTasks().getByName(LifecycleBasePlugin.CHECK_TASK_NAME).dependsOn(check);

        MironGenerate generate = project.getTasks().create(GENERATE_TASK, MironGenerate.class, task -> {
            task.setGroup(LifecycleBasePlugin.BUILD_GROUP);
            task.setDescription("Generates each MIRoN model's woven tree, MiniZinc model and data, io.json and "
                    + "RoQME runtime model into build/generated/miron.");
            task.setModels(extension.getModels());
            task.setOptions(extension);
            task.setOutputDir(new File(buildDir, "generated/miron"));
        });

        // Without java, assemble builds the artefacts; with it, assemble reaches them through the jar too.
        project.getTasks().getByName(LifecycleBasePlugin.ASSEMBLE_TASK_NAME).dependsOn(generate);
        project.getPlugins().withType(JavaPlugin.class, java -> {
            // "sourceSets" is a convention in Gradle 4.4.1 and an extension in current releases.
            SourceSet main = ((SourceSetContainer) project.property("sourceSets")).getByName(SourceSet.MAIN_SOURCE_SET_NAME);
            main.getResources().srcDir(generate.getOutputDir());
            project.getTasks().getByName(main.getProcessResourcesTaskName()).dependsOn(generate);
        });
    }
}
