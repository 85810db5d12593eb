package org.miron.gradle;

import java.io.File;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;

import org.gradle.api.DefaultTask;
import org.gradle.api.file.ConfigurableFileCollection;
import org.gradle.api.file.FileCollection;
import org.gradle.api.file.FileTree;
import org.gradle.api.tasks.InputFiles;
import org.gradle.api.tasks.Internal;
import org.gradle.api.tasks.OutputFile;
import org.gradle.api.tasks.SkipWhenEmpty;
import org.gradle.api.tasks.TaskAction;
import org.miron.generator.standalone.Diagnostic;
import org.miron.generator.standalone.ModelLoader;

/**
 * `checkMiron`: what `miron check` does for every .bt, .xml, .roqme and .miron file of the model
 * folders (with all they import). Its report (the warnings, when it passes) is its output, so an
 * unchanged model folder is UP-TO-DATE.
 */
public class MironCheck extends DefaultTask {
    // Fixed at configuration: a task action that reads Task.project is deprecated in current Gradle.
    private final ConfigurableFileCollection models = getProject().files();
    private final FileTree sources = ModelSources.sources(getProject(), models);
    private final File rootDir = getProject().getRootDir();
    private File report;

    /** The models whose folders are checked (the extension's, set by the plugin). */
    @Internal // its folders' files are the input
    public FileCollection getModels() {
        return models;
    }

    public void setModels(FileCollection models) {
        this.models.setFrom(models);
    }

    @InputFiles
    @SkipWhenEmpty
    public FileTree getSources() {
        return sources;
    }

    @OutputFile
    public File getReport() {
        return report;
    }

    public void setReport(File report) {
        this.report = report;
    }

    @TaskAction
    public void check() {
        List<File> files = new ArrayList<>(getSources().getFiles());
        files.sort(null);
        List<Diagnostic> diagnostics = CoreThread.call(() -> new ModelLoader(rootDir.toPath()).check(files));
        ModelReport.log(getLogger(), diagnostics);
        try {
            Files.createDirectories(report.getParentFile().toPath());
            Files.write(report.toPath(), diagnostics.stream().map(Diagnostic::toString).collect(Collectors.toList()),
                    StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        if (ModelLoader.hasErrors(diagnostics)) {
            throw ModelReport.failure(diagnostics);
        }
    }
}
