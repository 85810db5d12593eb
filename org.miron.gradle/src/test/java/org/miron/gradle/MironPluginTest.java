package org.miron.gradle;

import static org.gradle.testkit.runner.TaskOutcome.SUCCESS;
import static org.gradle.testkit.runner.TaskOutcome.UP_TO_DATE;
import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.jar.JarFile;

import org.gradle.testkit.runner.BuildResult;
import org.gradle.testkit.runner.TaskOutcome;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * The plugin in a user's build, as docs/gradle.md tells a user to write it: real projects in
 * temporary folders, built by this machine's Gradle (TestKit), the plugin and the core resolved from
 * mavenLocal. The reference for what is generated is `miron generate` itself.
 */
public class MironPluginTest {
    private static final String GENERATED = "build/generated/miron";

    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    private UserProject project(String buildFile) throws IOException {
        return UserProject.intralogistics(temp.getRoot().toPath().resolve("robot"), buildFile);
    }

    private static TaskOutcome outcome(BuildResult result, String task) {
        return result.task(":" + task) == null ? null : result.task(":" + task).getOutcome();
    }

    private static void assertSameFiles(Map<String, byte[]> expected, Map<String, byte[]> actual) {
        assertEquals(expected.keySet(), actual.keySet());
        expected.forEach((name, bytes) -> assertArrayEquals(name, bytes, actual.get(name)));
    }

    @Test
    public void aJavaProjectGeneratesWhatMironGenerateWritesIntoItsResources() throws Exception {
        UserProject robot = project(UserProject.buildscript() + "apply plugin: 'java'\napply plugin: 'org.miron.generate'\n");
        BuildResult result = robot.build("build");
        assertEquals(SUCCESS, outcome(result, "checkMiron"));
        assertEquals(SUCCESS, outcome(result, "generateMiron"));
        assertEquals(SUCCESS, outcome(result, "processResources"));

        Map<String, byte[]> generated = robot.files(GENERATED);
        assertTrue(generated.keySet().toString(), generated.containsKey("intralogistics.ext.xml"));
        assertTrue(generated.containsKey("intralogistics.mzn"));
        assertTrue(generated.containsKey("intralogistics.roqme.json"));
        assertSameFiles(robot.mironGenerate("build/generated/cli", "src/main/miron/intralogistics.miron"), generated);
        // The generated folder is a resource folder: the artefacts are in the jar.
        try (JarFile jar = new JarFile(robot.dir.resolve("build/libs/robot.jar").toFile())) {
            for (String name : generated.keySet()) {
                assertTrue(name + " in the jar", jar.getEntry(name) != null);
            }
        }
    }

    @Test
    public void withoutJavaAssembleGeneratesAgainOnlyWhenAModelOrAnImportChanges() throws Exception {
        UserProject robot = project(UserProject.buildscript() + "apply plugin: 'org.miron.generate'\n");
        assertEquals(SUCCESS, outcome(robot.build("assemble"), "generateMiron"));
        assertEquals(UP_TO_DATE, outcome(robot.build("assemble"), "generateMiron"));

        robot.append("src/main/miron/intralogistics.miron", "\n// a comment changes the model file\n");
        assertEquals(SUCCESS, outcome(robot.build("assemble"), "generateMiron"));
        assertEquals(UP_TO_DATE, outcome(robot.build("assemble"), "generateMiron"));

        // The imported tree: a new tree in it changes the woven file.
        byte[] before = robot.files(GENERATED).get("intralogistics.ext.xml");
        String bt = Files.readString(robot.dir.resolve("src/main/miron/intralogistics.bt"));
        robot.write("src/main/miron/intralogistics.bt", bt.replace("</root>",
                "  <BehaviorTree ID=\"Spare\">\n    <AlwaysSuccess/>\n  </BehaviorTree>\n</root>"));
        assertEquals(SUCCESS, outcome(robot.build("assemble"), "generateMiron"));
        assertFalse("the woven tree follows the imported one",
                java.util.Arrays.equals(before, robot.files(GENERATED).get("intralogistics.ext.xml")));

        assertEquals(SUCCESS, outcome(robot.build("check"), "checkMiron"));
        assertEquals(UP_TO_DATE, outcome(robot.build("check"), "checkMiron"));
    }

    @Test
    public void optionsAreMironGeneratesOptions() throws Exception {
        UserProject robot = project(UserProject.buildscript() + "apply plugin: 'org.miron.generate'\n"
                + "miron {\n    models = fileTree('src/main/miron') { include '**/*.miron' }\n"
                + "    btFormat = 4\n    weights = 'metric'\n}\n");
        robot.build("generateMiron");
        assertSameFiles(robot.mironGenerate("build/generated/cli", "src/main/miron/intralogistics.miron",
                "--bt-format", "4", "--weights", "metric"), robot.files(GENERATED));
        assertTrue(new String(robot.files(GENERATED).get("intralogistics.ext.xml")).contains("BTCPP_format=\"4\""));

        robot.append("build.gradle", "miron.weights = 'most'\n");
        BuildResult result = robot.buildAndFail("generateMiron");
        assertTrue(result.getOutput(), result.getOutput().contains("miron.weights must be need or metric, not 'most'"));
    }

    @Test
    public void aModelErrorFailsTheBuildWithItsLineAndNoStackTrace() throws Exception {
        UserProject robot = project(UserProject.buildscript() + "apply plugin: 'java'\napply plugin: 'org.miron.generate'\n");
        robot.write("src/main/miron/broken.miron", "import \"intralogistics.bt\" as main\n"
                + "import \"intralogistics.roqme\" as roqme\n\n"
                + "@varpoint task : enum { dock : main.Charge, nominal : preset } in main.NoSuchNode\n");
        BuildResult generate = robot.buildAndFail("jar");
        String out = generate.getOutput();
        assertEquals(TaskOutcome.FAILED, outcome(generate, "generateMiron"));
        assertTrue(out, out.matches("(?s).*src/main/miron/broken\\.miron:4:\\d+: error \\[roqme\\.unknown-reference\\]: [^\\n]*NoSuchNode.*"));
        assertNoStackTrace(out);
        assertTrue("all or nothing: the valid model is not generated either", robot.files(GENERATED).isEmpty());

        // checkMiron checks the imported tree too: a decorator without child, at its line.
        robot.write("src/main/miron/broken.miron", "import \"broken.bt\" as main\n");
        robot.write("src/main/miron/broken.bt", "<root main_tree_to_execute=\"M\">\n  <BehaviorTree ID=\"M\">\n"
                + "    <Inverter/>\n  </BehaviorTree>\n</root>\n");
        BuildResult check = robot.buildAndFail("check");
        assertEquals(TaskOutcome.FAILED, outcome(check, "checkMiron"));
        assertTrue(check.getOutput(), check.getOutput().matches(
                "(?s).*src/main/miron/broken\\.bt:3:\\d+: error \\[bt\\.decorator-child-count\\]: .*"));
        assertNoStackTrace(check.getOutput());
    }

    @Test
    public void anImportFromOutsideTheModelFoldersIsToldUntilItsFolderIsAModelFolder() throws Exception {
        UserProject robot = project(UserProject.buildscript() + "apply plugin: 'org.miron.generate'\n");
        Files.createDirectories(robot.dir.resolve("common"));
        Files.move(robot.dir.resolve("src/main/miron/intralogistics.roqme"), robot.dir.resolve("common/intralogistics.roqme"));
        String model = Files.readString(robot.dir.resolve("src/main/miron/intralogistics.miron"));
        robot.write("src/main/miron/intralogistics.miron",
                model.replace("import \"intralogistics.roqme\"", "import \"../../../common/intralogistics.roqme\""));
        String warning = "common/intralogistics.roqme: warning: imported from outside the model folders";
        String out = robot.build("assemble").getOutput();
        assertTrue(out, out.contains(warning));
        assertFalse("named relative to the project, as diagnostics are", out.contains(robot.dir.resolve("common").toString()));

        robot.append("build.gradle", "miron.models = [fileTree('src/main/miron') { include '**/*.miron' }, 'common']\n");
        BuildResult result = robot.build("assemble");
        assertFalse(result.getOutput(), result.getOutput().contains(warning));
        robot.append("common/intralogistics.roqme", "\n// a comment changes the imported file\n");
        assertEquals(SUCCESS, outcome(robot.build("assemble"), "generateMiron"));
    }

    /** The stack the core gets: `./miron`'s, where a deeply nested tree parses (a Gradle thread's overflows). */
    @Test
    public void aDeeplyNestedTreeIsCheckedAsTheCommandLineChecksIt() throws Exception {
        UserProject robot = project(UserProject.buildscript() + "apply plugin: 'org.miron.generate'\n");
        robot.write("src/main/miron/deep.bt", "<root main_tree_to_execute=\"Deep\">\n<BehaviorTree ID=\"Deep\">\n"
                + "<Sequence>".repeat(3000) + "<AlwaysSuccess/>" + "</Sequence>".repeat(3000) + "\n</BehaviorTree>\n</root>\n");
        BuildResult result = robot.build("checkMiron");
        assertEquals(SUCCESS, outcome(result, "checkMiron"));
        assertNoStackTrace(result.getOutput());
    }

    private static void assertNoStackTrace(String output) {
        assertFalse(output, output.contains("\tat "));
        assertFalse(output, output.contains("Exception"));
    }

    /**
     * The plugins {} DSL finds a plugin by its marker, org.miron.generate:org.miron.generate.gradle.plugin,
     * which depends on the plugin's module. Gradle 4.4.1 resolves no -SNAPSHOT version there ("snapshot
     * plugin versions are not supported"), so what is checked here is the marker the build published.
     */
    @Test
    public void theMarkerForThePluginsBlockNamesThePlugin() throws Exception {
        Path pom = Path.of(System.getProperty("user.home"), ".m2/repository/org/miron/generate/org.miron.generate.gradle.plugin",
                UserProject.VERSION, "org.miron.generate.gradle.plugin-" + UserProject.VERSION + ".pom");
        String text = Files.readString(pom);
        assertTrue(text, text.replaceAll("\\s+", "").contains("<dependency><groupId>org.miron</groupId>"
                + "<artifactId>org.miron.gradle</artifactId><version>" + UserProject.VERSION + "</version></dependency>"));
    }
}
