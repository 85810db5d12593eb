package org.miron.lsp.server;

import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

import org.eclipse.lsp4j.Hover;
import org.eclipse.lsp4j.HoverParams;
import org.eclipse.lsp4j.TextDocumentIdentifier;
import org.junit.AfterClass;
import org.junit.BeforeClass;
import org.junit.Test;
import org.miron.testkit.Examples;
import org.miron.testkit.Folders;
import org.miron.testkit.lsp.LspClient;

/**
 * Issue 22, editor help: hovering an observation shows each action's likelihood ratio and
 * survival; hovering a property or beliefvar its reference, survival and the observations that
 * move it, with the numbers of docs/roqme-runtime.md.
 */
public class EvidenceHoverLspTest {
    private static Path workspace;
    private static LspClient client;
    private static String roqmeText;
    private static String roqmeUri;

    @BeforeClass
    public static void setUp() throws Exception {
        workspace = Examples.copy("intralogistics");
        client = new LspClient();
        client.initialize(workspace);
        roqmeText = Files.readString(workspace.resolve("intralogistics.roqme"))
                + "\nbeliefvar complaints survival 1 hour\n"
                + "observation complaint : EmergencyStop { reinforces complaints low clears safety }\n";
        roqmeUri = client.open(workspace.resolve("intralogistics.roqme"), roqmeText);
        client.awaitDiagnostics(roqmeUri, d -> true);
    }

    @AfterClass
    public static void tearDown() throws Exception {
        client.close();
        Folders.delete(workspace);
    }

    private static String hover(String after) throws Exception {
        Hover hover = client.server().getTextDocumentService()
                .hover(new HoverParams(new TextDocumentIdentifier(roqmeUri), IntralogisticsLspTest.positionAfter(roqmeText, after)))
                .get(60, TimeUnit.SECONDS);
        return hover == null || hover.getContents() == null ? "" : hover.getContents().getRight().getValue();
    }

    @Test
    public void anObservationShowsTheRatioAndSurvivalOfEachAction() throws Exception {
        String tooClose = hover("observation tooCl");
        assertTrue(tooClose, tooClose.contains("Humans very close undermine safety."));
        assertTrue(tooClose, tooClose.contains("undermines `safety` HIGH: likelihood ratio 3.333, survival 5 minutes (the default)"));
        String emergency = hover("observation emerg");
        assertTrue(emergency, emergency.endsWith("undermines `safety` VERYHIGH: likelihood ratio 10, survival 5 minutes"));
        String delivered = hover("observation deliv");
        assertTrue(delivered, delivered.contains(
                "reinforces `mission_completion` MEDIUM: likelihood ratio 0.5, survival 30 minutes (of mission_completion)"));
        assertTrue(delivered, delivered.contains("`starts sinceLastDelivery`"));
        String batteryHigh = hover("observation batteryHi");
        assertTrue(batteryHigh, batteryHigh.contains("reinforces `power_autonomy` HIGH: likelihood ratio 0.3"));
        String low = hover("observation batteryLo");
        assertTrue(low, low.contains("undermines `power_autonomy` VERYHIGH: likelihood ratio 10,"));
        String openSpace = hover("observation openSp");
        assertTrue(openSpace, openSpace.contains("reinforces `safety` LOW: likelihood ratio 0.7,"));
        String complaint = hover("observation compl");
        assertTrue(complaint, complaint.contains("clears `safety` (drops its evidence)"));
    }

    @Test
    public void aBeliefShowsItsReferenceSurvivalAndWhatMovesIt() throws Exception {
        String safety = hover("property saf");
        assertTrue(safety, safety.contains("**property safety**: reference 0.7, evidence survives 5 minutes (the default)"));
        assertTrue(safety, safety.contains("- `tooClose`: undermines HIGH: likelihood ratio 3.333, survival 5 minutes (the default)"));
        assertTrue(safety, safety.contains("- `emergency`: undermines VERYHIGH: likelihood ratio 10, survival 5 minutes"));
        assertTrue(safety, safety.contains("- `openSpace`: reinforces LOW: likelihood ratio 0.7"));
        assertTrue(safety, safety.contains("- `complaint`: clears its evidence"));
        String mission = hover("property mission_compl");
        assertTrue(mission, mission.contains("reference 0.5, evidence survives 30 minutes unless"));
        assertTrue(mission, mission.contains("- `idle`: undermines LOW: likelihood ratio 1.429, survival 30 minutes (of mission_completion)"));
        String complaints = hover("beliefvar compl");
        assertTrue(complaints, complaints.contains("**beliefvar complaints**: reference 0.5 (the default), evidence survives 1 hour"));
        assertTrue(complaints, complaints.contains("- `complaint`: reinforces LOW: likelihood ratio 0.7, survival 1 hour (of complaints)"));
    }

    @Test
    public void aPropertyReadFromTheMironShowsTheObservationsOfTheRoqme() throws Exception {
        Path miron = workspace.resolve("intralogistics.miron");
        String text = Files.readString(miron);
        String uri = client.open(miron, text);
        client.awaitDiagnostics(uri, d -> true);
        Hover hover = client.server().getTextDocumentService()
                .hover(new HoverParams(new TextDocumentIdentifier(uri), IntralogisticsLspTest.positionAfter(text, "roqme.power_auto")))
                .get(60, TimeUnit.SECONDS);
        String shown = hover.getContents().getRight().getValue();
        assertTrue(shown, shown.contains("**property power_autonomy**: reference 0.5"));
        assertTrue(shown, shown.contains("`batteryLow`: undermines VERYHIGH: likelihood ratio 10"));
    }
}
