package org.miron.gradle;

import java.io.File;
import java.util.ArrayList;
import java.util.List;

import org.gradle.api.DefaultTask;
import org.gradle.api.GradleException;
import org.gradle.api.file.ConfigurableFileCollection;
import org.gradle.api.file.FileCollection;
import org.gradle.api.file.FileTree;
import org.gradle.api.tasks.Input;
import org.gradle.api.tasks.InputFiles;
import org.gradle.api.tasks.Optional;
import org.gradle.api.tasks.OutputDirectory;
import org.gradle.api.tasks.SkipWhenEmpty;
import org.gradle.api.tasks.TaskAction;
import org.miron.generator.WeightPolicy;
import org.miron.generator.standalone.BatchGeneration;
import org.miron.generator.standalone.Diagnostic;
import org.miron.generator.standalone.ModelLoader;

/**
 * `generateMiron`: what `miron generate -o DIR` does for the models, through the same core
 * (BatchGeneration): all or nothing, so a model with errors leaves the output folder empty.
 * Inputs are the models and every model-language file of their folders (their imports), and the
 * options; a run starts from an empty folder, so a removed model leaves nothing behind.
 */
public class MironGenerate extends DefaultTask {
    // Fixed at configuration: a task action that reads Task.project is deprecated in current Gradle.
    private final ConfigurableFileCollection models = getProject().files();
    private final FileTree sources = ModelSources.sources(getProject(), models);
    private final File rootDir = getProject().getRootDir();
    private File outputDir;
    private MironExtension options;

    @InputFiles
    @SkipWhenEmpty
    public FileTree getModels() {
        return ModelSources.models(models);
    }

    public void setModels(FileCollection models) {
        this.models.setFrom(models);
    }

    @InputFiles
    public FileTree getSources() {
        return sources;
    }

    @Input
    public String getWeights() {
        return options.getWeights();
    }

    @Input
    @Optional
    public Integer getBtFormat() {
        return options.getBtFormat();
    }

    /** Where the options come from: the extension, read when the task runs. */
    public void setOptions(MironExtension options) {
        this.options = options;
    }

    @OutputDirectory
    public File getOutputDir() {
        return outputDir;
    }

    public void setOutputDir(File outputDir) {
        this.outputDir = outputDir;
    }

    @TaskAction
    public void generate() {
        WeightPolicy weights = WeightPolicy.of(getWeights());
        if (weights == null) {
            throw new GradleException("miron.weights must be need or metric, not '" + getWeights() + "'");
        }
        Integer btFormat = getBtFormat();
        if (btFormat != null && btFormat != 3 && btFormat != 4) {
            throw new GradleException("miron.btFormat must be 3 or 4, not " + btFormat);
        }
        OutputFolder.empty(outputDir);
        List<File> files = new ArrayList<>(getModels().getFiles());
        files.sort(null);
        // The loader sets the languages up: inside the core's thread too.
        ModelLoader[] loader = new ModelLoader[1];
        BatchGeneration.Outcome outcome = CoreThread.call(() -> {
            loader[0] = new ModelLoader(rootDir.toPath());
            return new BatchGeneration(loader[0], weights, btFormat).generate(files, outputDir.toPath());
        });
        List<Diagnostic> problems = new ArrayList<>(outcome.validation());
        problems.addAll(outcome.generationErrors());
        ModelReport.log(getLogger(), problems);
        if (outcome.stage() == BatchGeneration.Stage.WRITE_FAILED) {
            throw new GradleException(outputDir + ": cannot write: " + outcome.writeError());
        }
        if (!outcome.succeeded()) {
            throw ModelReport.failure(problems);
        }
        outcome.written().forEach(name -> getLogger().info("wrote {}", new File(outputDir, name)));
        ImportsOutsideInputs.warn(getLogger(), loader[0].loadedFiles(), getSources().getFiles(), rootDir);
    }
}
