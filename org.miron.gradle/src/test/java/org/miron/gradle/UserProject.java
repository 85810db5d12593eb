package org.miron.gradle;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;

import org.gradle.testkit.runner.BuildResult;
import org.gradle.testkit.runner.GradleRunner;
import org.miron.testkit.RepositoryRoot;

/**
 * A user's project in a temporary folder outside the repository, built by this machine's Gradle
 * through TestKit. Its build takes the plugin and the core modules from mavenLocal, where the
 * test task has them published first (`publishToMavenLocal`), and everything else from Maven
 * Central, as a user's build does.
 */
final class UserProject {
    static final String VERSION = System.getProperty("miron.version");

    final Path dir;

    UserProject(Path dir) {
        this.dir = dir;
    }

    /** The buildscript block of docs/gradle.md. */
    static String buildscript() {
        return "buildscript {\n"
                + "    repositories { mavenLocal(); mavenCentral() }\n"
                + "    dependencies { classpath 'org.miron:org.miron.gradle:" + VERSION + "' }\n"
                + "}\n";
    }

    /** A project with the intralogistics example in src/main/miron and the given build file. */
    static UserProject intralogistics(Path dir, String buildFile) throws IOException {
        UserProject project = new UserProject(dir);
        for (String name : List.of("intralogistics.miron", "intralogistics.bt", "intralogistics.roqme")) {
            project.write("src/main/miron/" + name,
                    Files.readString(RepositoryRoot.path().resolve("examples/intralogistics/" + name)));
        }
        project.write("settings.gradle", "rootProject.name = 'robot'\n");
        project.write("build.gradle", buildFile);
        return project;
    }

    Path write(String name, String text) throws IOException {
        Path file = dir.resolve(name);
        Files.createDirectories(file.getParent());
        Files.writeString(file, text);
        return file;
    }

    void append(String name, String text) throws IOException {
        Files.writeString(dir.resolve(name), text, java.nio.file.StandardOpenOption.APPEND);
    }

    BuildResult build(String... args) {
        return runner(args).build();
    }

    BuildResult buildAndFail(String... args) {
        return runner(args).buildAndFail();
    }

    private GradleRunner runner(String... args) {
        return GradleRunner.create().withGradleInstallation(TestKitGradle.installation())
                .withTestKitDir(new File(System.getProperty("miron.testkit.dir"), "home"))
                .withProjectDir(dir.toFile()).withArguments(args).forwardOutput();
    }

    /** Every file below a folder of the project, by path relative to it, with its bytes. */
    Map<String, byte[]> files(String folder) throws IOException {
        Map<String, byte[]> files = new TreeMap<>();
        Path root = dir.resolve(folder);
        if (!Files.isDirectory(root)) {
            return files;
        }
        try (Stream<Path> paths = Files.walk(root)) {
            for (Path p : (Iterable<Path>) paths.filter(Files::isRegularFile)::iterator) {
                files.put(root.relativize(p).toString(), Files.readAllBytes(p));
            }
        }
        return files;
    }

    /**
     * What `miron generate -o OUT MODEL [options]` writes, run as the command line in this project's
     * folder: the reference for generateMiron's bytes.
     */
    Map<String, byte[]> mironGenerate(String out, String model, String... options) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(List.of(javaExecutable(), "-Xss4m", "-cp",
                System.getProperty("miron.cli.classpath"), "org.miron.cli.MironCli", "generate", "-o", out, model));
        command.addAll(List.of(options));
        Process process = new ProcessBuilder(command).directory(dir.toFile()).redirectErrorStream(true).start();
        String output = new String(process.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        if (process.waitFor() != 0) {
            throw new AssertionError("miron generate failed:\n" + output);
        }
        return files(out);
    }

    private static String javaExecutable() {
        return Path.of(System.getProperty("java.home"), "bin", "java").toString();
    }
}
