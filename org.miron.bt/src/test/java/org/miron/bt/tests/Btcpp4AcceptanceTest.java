package org.miron.bt.tests;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertFalse;
import static org.junit.Assert.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

import org.eclipse.xtext.diagnostics.Severity;
import org.eclipse.xtext.validation.Issue;
import org.junit.Before;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;
import org.miron.testkit.Btcpp4Loader;
import org.miron.testkit.Btcpp4Python;

/**
 * The real BehaviorTree.CPP 4 library decides: our valid version-4 files load in it, and on the
 * probe trees (src/test/resources/btcpp4/probes.txt) we reject exactly what it rejects, except
 * where the probe says we are deliberately stricter.
 */
public class Btcpp4AcceptanceTest {
    @Rule
    public TemporaryFolder folder = new TemporaryFolder();

    @Before
    public void oracle() {
        Btcpp4Python.assumeInstalled();
    }

    @Test
    public void validVersion4FilesLoadInTheLibrary() throws Exception {
        List<File> files = BtFiles.filesIn("valid").stream()
                .filter(f -> BtFiles.model(BtFiles.load(f)).formatVersion() == 4).collect(Collectors.toList());
        assertTrue("no version-4 valid files", files.size() >= 5);
        for (Map.Entry<File, Btcpp4Loader.Verdict> entry : Btcpp4Loader.load(files).entrySet()) {
            assertTrue(entry.getKey().getName() + ": " + entry.getValue().message, entry.getValue().loaded);
        }
    }

    @Test
    public void weRejectWhatTheLibraryRejectsAndAcceptWhatItLoads() throws Exception {
        List<String> lines = Files.readAllLines(new File(BtFiles.RESOURCES.getParentFile(), "btcpp4/probes.txt").toPath());
        List<File> files = new ArrayList<>();
        List<Boolean> stricter = new ArrayList<>();
        for (String line : lines) {
            if (line.isBlank() || line.startsWith("#")) {
                continue;
            }
            boolean strict = line.startsWith("stricter:");
            String body = strict ? line.substring("stricter:".length()).trim() : line;
            File file = folder.newFile("probe" + files.size() + ".bt");
            Files.writeString(file.toPath(), "<root BTCPP_format=\"4\" main_tree_to_execute=\"Main\">\n"
                    + "  <BehaviorTree ID=\"Main\">" + body + "</BehaviorTree>\n"
                    + "  <BehaviorTree ID=\"S\"><AlwaysSuccess/></BehaviorTree>\n</root>\n", StandardCharsets.UTF_8);
            files.add(file);
            stricter.add(strict);
        }
        Map<File, Btcpp4Loader.Verdict> verdicts = Btcpp4Loader.load(files);
        List<String> disagreements = new ArrayList<>();
        int rejected = 0;
        for (int i = 0; i < files.size(); i++) {
            File file = files.get(i);
            Btcpp4Loader.Verdict verdict = verdicts.get(file);
            List<Issue> errors = BtFiles.validate(BtFiles.load(file)).stream()
                    .filter(issue -> issue.getSeverity() == Severity.ERROR).collect(Collectors.toList());
            String tree = Files.readAllLines(file.toPath()).get(1).trim();
            if (!verdict.loaded) {
                rejected++;
            }
            if (!verdict.loaded && errors.isEmpty()) {
                disagreements.add("library rejects, we accept: " + tree + "\n    " + verdict.message);
            } else if (verdict.loaded && !stricter.get(i) && !errors.isEmpty()) {
                disagreements.add("library loads, we reject: " + tree + "\n    " + BtFiles.describe(errors));
            } else if (stricter.get(i) && (!verdict.loaded || errors.isEmpty())) {
                disagreements.add("marked stricter, but library " + (verdict.loaded ? "loads" : "rejects")
                        + " and we report " + errors.size() + " errors: " + tree);
            }
        }
        assertEquals(String.join("\n", disagreements), 0, disagreements.size());
        assertFalse("the probes must include trees the library rejects", rejected == 0);
    }
}
