package org.miron.eclipse.tests;

import static org.junit.Assert.assertArrayEquals;
import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.junit.Assume.assumeTrue;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.AfterClass;
import org.junit.BeforeClass;
import org.junit.ClassRule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.testkit.RepositoryRoot;

/**
 * The builder in a real Eclipse IDE workbench (gradle/eclipse-workbench.gradle: the platform from
 * Maven Central, our update site's bundles, the driver bundle WorkbenchDriver) on the Temurin 25
 * JDK under Xvfb. The driver does what a user does on the intralogistics example; this test holds
 * what it saw to what the command line says of the same files: the markers to `miron check
 * --format json`, generated/ to `miron generate` byte for byte. The Problems view's screenshot is
 * kept in build/reports/workbench/ (problems.png), with the workbench's log and what the driver saw.
 */
public class WorkbenchTest {
    @ClassRule
    public static final TemporaryFolder tmp = new TemporaryFolder();

    /** The broken line of the tree: a SubTree ID no tree has (line 17 of intralogistics.bt). */
    private static final String GOOD = "<SubTreePlus ID=\"GoTo\" __shared_blackboard=\"false\" x_input=\"-9.33\"";
    private static final String BAD = "<SubTreePlus ID=\"GoTooo\" __shared_blackboard=\"false\" x_input=\"-9.33\"";
    private static final List<String> SIX = List.of("intralogistics.dzn", "intralogistics.ext.xml",
            "intralogistics.io.json", "intralogistics.mzn", "intralogistics.requirements.json",
            "intralogistics.roqme.json");

    private static Path input;
    private static Path reference;
    private static Map<String, List<String>> seen;
    private static Process xvfb;
    private static double seconds;

    @BeforeClass
    public static void runTheWorkbench() throws Exception {
        File java = new File(System.getProperty("miron.workbench.java"));
        assumeTrue("no Java 21+ for the workbench at " + java + " (MIRON_WORKBENCH_JAVA)", java.canExecute());
        assumeTrue("no Xvfb (scripts/ensure-eclipse-workbench.sh installs it)", onPath("Xvfb"));
        assumeTrue("no ImageMagick's import (scripts/ensure-eclipse-workbench.sh installs it)", onPath("import"));
        input = tmp.newFolder("input").toPath();
        Path example = RepositoryRoot.resolve("examples/intralogistics");
        for (String name : List.of("intralogistics.bt", "intralogistics.roqme", "intralogistics.miron")) {
            Files.copy(example.resolve(name), input.resolve(name));
        }
        String tree = Files.readString(input.resolve("intralogistics.bt"));
        assertEquals("line 17 of the tree", GOOD, tree.lines().toList().get(16).trim().substring(0, GOOD.length()));
        Files.createDirectories(input.resolve("broken"));
        Files.writeString(input.resolve("broken/intralogistics.bt"), tree.replace(GOOD, BAD));
        Files.copy(input.resolve("intralogistics.roqme"), input.resolve("broken/intralogistics.roqme"));
        Files.copy(input.resolve("intralogistics.miron"), input.resolve("broken/intralogistics.miron"));
        Files.writeString(input.resolve("garbage.bt"), "<root>\n  <BehaviorTree ID=\"X\">\n    <Sequence>\n</root>\n");
        Files.writeString(input.resolve("notatree.xml"), "<project>\n  <modelVersion>4.0.0</modelVersion>\n</project>\n");

        reference = tmp.newFolder("reference").toPath();
        cli(input, "generate", "intralogistics.miron", "-o", reference.toString());

        Path reports = RepositoryRoot.resolve("org.miron.eclipse/build/reports/workbench");
        Files.createDirectories(reports);
        Files.deleteIfExists(reports.resolve("problems.png"));
        // Xvfb picks a free display itself (others may run theirs) and tells its number on stdout.
        xvfb = new ProcessBuilder("Xvfb", "-displayfd", "1", "-screen", "0", "1280x800x24", "-nolisten", "tcp")
                .redirectError(reports.resolve("xvfb.log").toFile()).start();
        String display = new BufferedReader(new InputStreamReader(xvfb.getInputStream(),
                StandardCharsets.US_ASCII)).readLine();
        assertTrue("Xvfb did not start: " + reports.resolve("xvfb.log"), display != null && display.matches("\\d+"));
        Path install = Path.of(System.getProperty("miron.workbench.install"));
        Path run = tmp.newFolder("run").toPath();
        Files.createDirectories(run.resolve("configuration"));
        Files.copy(install.resolve("configuration/config.ini"), run.resolve("configuration/config.ini"));
        Path result = run.resolve("result.txt");
        ProcessBuilder eclipse = new ProcessBuilder(java.getPath(), "--enable-native-access=ALL-UNNAMED", "-Xmx1g",
                "-Dmiron.workbench.input=" + input, "-Dmiron.workbench.result=" + result,
                "-Dmiron.workbench.screenshot=" + reports.resolve("problems.png"),
                "-jar", install.resolve("launcher.jar").toString(),
                "-install", install.toString(), "-configuration", run.resolve("configuration").toString(),
                "-data", run.resolve("ws").toString(), "-consoleLog", "-clean")
                .redirectErrorStream(true).redirectOutput(reports.resolve("workbench.log").toFile());
        eclipse.environment().put("DISPLAY", ":" + display);
        eclipse.environment().put("GDK_BACKEND", "x11");
        eclipse.environment().put("NO_AT_BRIDGE", "1");
        long start = System.nanoTime();
        Process process = eclipse.start();
        boolean exited = process.waitFor(5, TimeUnit.MINUTES);
        seconds = (System.nanoTime() - start) / 1e9;
        if (!exited) {
            process.destroyForcibly();
        }
        System.out.printf("WorkbenchTest: the workbench ran %.1f s (log: %s)%n", seconds, reports.resolve("workbench.log"));
        assertTrue("the workbench did not exit within 5 minutes: " + reports.resolve("workbench.log"), exited);
        assertTrue("the driver wrote nothing: " + reports.resolve("workbench.log"), Files.exists(result));
        Files.copy(result, reports.resolve("driver.txt"), StandardCopyOption.REPLACE_EXISTING);
        seen = new LinkedHashMap<>();
        for (String line : Files.readAllLines(result)) {
            int eq = line.indexOf('=');
            seen.computeIfAbsent(line.substring(0, eq), k -> new ArrayList<>()).add(line.substring(eq + 1));
        }
    }

    @AfterClass
    public static void stopXvfb() {
        if (xvfb != null) {
            xvfb.destroy();
        }
    }

    private static String one(String key) {
        List<String> values = seen.get(key);
        assertTrue("the driver did not say " + key + ": " + seen, values != null && values.size() == 1);
        return values.get(0);
    }

    @Test
    public void theDriverRanToTheEndWithNothingInTheErrorLog() {
        assertEquals(seen.toString(), "true", one("done"));
        assertEquals(String.valueOf(seen.get("exception")), null, seen.get("exception"));
        assertEquals(String.valueOf(seen.get("errorLog")), null, seen.get("errorLog"));
        assertTrue("the workbench took " + seconds + " s", seconds < 240);
    }

    @Test
    public void addMironNatureConfiguresTheBuilder() {
        // Configure > Add MIRoN Nature on the project, gone once the project has the nature.
        assertTrue(one("configureMenu"), one("configureMenu").contains("org.miron.eclipse.addNature:visible"));
        assertTrue(one("configureMenuAfter"), one("configureMenuAfter").contains("org.miron.eclipse.addNature:hidden"));
        assertEquals("0", one("markersBeforeNature"));
        assertEquals("true", one("nature"));
        assertTrue(one("builders"), one("builders").contains("org.miron.eclipse.builder"));
    }

    @Test
    public void theValidExampleHasTheMarkersMironCheckGives() throws Exception {
        assertEquals(expectedMarkers(input, "intralogistics.miron").toString(), withoutRanges(one("markersValid")));
        assertEquals(expectedMarkers(input, "intralogistics.miron").toString(), withoutRanges(one("markersFixed")));
    }

    @Test
    public void theBuildGeneratesWhatMironGenerateWritesIntoADerivedFolder() throws Exception {
        assertEquals(String.join(",", SIX), one("generated"));
        assertEquals("true", one("generatedDerived"));
        sameBytes("first");
    }

    @Test
    public void aBrokenTreeAndAFileThatFailsToParseGetTheMarkersOfMironCheck() throws Exception {
        String broken = one("markersBroken");
        // The tree's marker: line 17, code bt.unknown-subtree, over the ID the CLI points at.
        Matcher tree = Pattern.compile("intralogistics\\.bt:17:(\\d+)-(\\d+):error:bt\\.unknown-subtree:[^|]*GoTooo")
                .matcher(broken);
        assertTrue(broken, tree.find());
        String text = Files.readString(input.resolve("broken/intralogistics.bt"));
        assertEquals("\"GoTooo\"", text.substring(Integer.parseInt(tree.group(1)), Integer.parseInt(tree.group(2))));
        // Exactly the problems `miron check` finds in the same files; one for the file that fails to parse.
        TreeSet<String> expected = new TreeSet<>(expectedMarkers(input.resolve("broken"), "intralogistics.miron"));
        List<String> garbage = expectedMarkers(input, "garbage.bt");
        assertEquals(garbage.toString(), 1, garbage.size());
        expected.addAll(garbage);
        assertEquals(expected.toString(), withoutRanges(broken));
        assertTrue(broken, !broken.contains("notatree.xml"));
        assertTrue(broken, !broken.contains("NOT-A-PROBLEM"));
    }

    @Test
    public void aModelWithErrorsWritesNothingAndTheFixRegeneratesItsImporter() throws Exception {
        assertEquals("absent", one("generatedWhileBroken"));
        assertEquals(String.join(",", SIX), one("generatedFixed"));
        sameBytes("fixed");
    }

    @Test
    public void theGenerateCommandWritesTheSameFiles() throws Exception {
        assertEquals(String.join(",", SIX), one("generatedByCommand"));
        sameBytes("command");
    }

    @Test
    public void theProblemsViewIsOnTheScreenshot() throws Exception {
        Path png = RepositoryRoot.resolve("org.miron.eclipse/build/reports/workbench/problems.png");
        assertTrue(png + " missing", Files.exists(png));
        assertTrue("an empty screenshot", Files.size(png) > 20_000);
    }

    private static void sameBytes(String copy) throws IOException {
        for (String name : SIX) {
            assertArrayEquals(copy + "/" + name, Files.readAllBytes(reference.resolve(name)),
                    Files.readAllBytes(input.resolve("out").resolve(copy).resolve(name)));
        }
    }

    /** What `miron check --format json FILE` says, run in dir, as the driver prints markers, without ranges. */
    private static List<String> expectedMarkers(Path dir, String file) throws Exception {
        String out = cli(dir, "check", "--format", "json", file);
        TreeSet<String> markers = new TreeSet<>();
        Pattern field = Pattern.compile("\"(file|line|severity|code|message)\":(\"((?:[^\"\\\\]|\\\\.)*)\"|\\d+|null)");
        for (String line : out.lines().toList()) {
            Map<String, String> values = new LinkedHashMap<>();
            Matcher m = field.matcher(line);
            while (m.find()) {
                values.putIfAbsent(m.group(1), m.group(3) != null ? m.group(3).replace("\\\"", "\"") : m.group(2));
            }
            if (values.containsKey("file")) {
                markers.add(Path.of(values.get("file")).getFileName() + ":" + values.get("line") + ":"
                        + values.get("severity") + ":" + ("null".equals(values.get("code")) ? "" : values.get("code"))
                        + ":" + values.get("message"));
            }
        }
        return new ArrayList<>(markers);
    }

    private static String withoutRanges(String markers) {
        if (markers.isEmpty()) {
            return "[]";
        }
        TreeSet<String> out = new TreeSet<>();
        for (String m : markers.split(" \\| ")) {
            out.add(m.replaceFirst("^([^:]+:\\d+):-?\\d+--?\\d+:", "$1:"));
        }
        return out.toString();
    }

    /** Runs the `miron` command's main class (org.miron.cli) in dir; its standard output. */
    private static String cli(Path dir, String... args) throws Exception {
        List<String> command = new ArrayList<>(List.of(
                Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xss4m",
                "-cp", System.getProperty("miron.cli.classpath"), "org.miron.cli.MironCli"));
        command.addAll(List.of(args));
        Path out = Files.createTempFile(tmp.getRoot().toPath(), "cli", ".out");
        Process p = new ProcessBuilder(command).directory(dir.toFile()).redirectOutput(out.toFile())
                .redirectError(ProcessBuilder.Redirect.INHERIT).start();
        assertTrue("miron " + String.join(" ", args) + " took over 2 minutes", p.waitFor(2, TimeUnit.MINUTES));
        return Files.readString(out, StandardCharsets.UTF_8);
    }

    private static boolean onPath(String command) {
        for (String dir : System.getenv().getOrDefault("PATH", "").split(File.pathSeparator)) {
            if (new File(dir, command).canExecute()) {
                return true;
            }
        }
        return false;
    }
}
