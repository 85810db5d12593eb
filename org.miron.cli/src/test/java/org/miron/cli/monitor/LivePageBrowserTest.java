package org.miron.cli.monitor;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.Set;

import org.junit.Assume;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

import com.fasterxml.jackson.databind.JsonNode;
import org.miron.testkit.Examples;

/**
 * The live page in headless Chromium while `miron demo --monitor` runs the hospital example; the
 * assertions read the DOM the browser built: node statuses change as the tree runs, and the
 * decision to charge first moves the outline of the preparation Switch from its default branch to
 * ChargeFirst (node 0.1.1.0); a requirement the scenario violates (the corridor is never to be dense:
 * it is from 9 s to 13 s) is listed as violated with the values then. Skipped, saying so, where no
 * Chromium is installed.
 */
public class LivePageBrowserTest {
    private static final long TIMEOUT_MS = 120_000;
    private static final String PREPARATION = "document.querySelector('#varpoints tr[data-name=\"preparation\"] td')";
    private static final String CHARGE_FIRST = "document.querySelector('#tree g[data-id=\"0.1.1.0\"]').classList";
    private static final String VIOLATIONS = "Array.from(document.querySelectorAll('#requirements tr.violated'))"
            + ".map(tr=>tr.textContent).join('|')";

    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    @Test
    public void statusesAndTheActiveVariantChangeInTheBrowser() throws Exception {
        String chromium = HeadlessChromium.find().orElse(null);
        if (chromium == null) {
            System.err.println("LivePageBrowserTest: skipped, no chromium on the PATH (apt-get install chromium)");
        }
        Assume.assumeNotNull(chromium);
        // The browser first: its start (seconds on a fresh machine) must not eat the demo's window.
        try (HeadlessChromium browser = new HeadlessChromium(chromium, temp.newFolder("profile").toPath())) {
            Path model = Examples.copy("hospital-delivery").resolve("hospital.miron");
            Files.writeString(model, Files.readString(model)
                    + "\nrequirement neverDense : never qos.crowding = qos::Crowding::DENSE\n");
            MonitoredDemo demo = new MonitoredDemo(model, temp.newFolder("demo").getPath(), "1.0"); // real time: the charge window lasts seconds even on a loaded machine
            long end = System.currentTimeMillis() + TIMEOUT_MS;
            String url = demo.awaitUrl(TIMEOUT_MS);
            assertTrue(demo.printed(), url != null);
            browser.open(url);
            // Statuses change: several different sets of running nodes are seen while the tree runs.
            Set<String> runningSets = new HashSet<>();
            boolean sawDefault = false;
            boolean sawCharge = false;
            String violations = "";
            while (System.currentTimeMillis() < end && !(runningSets.size() >= 3 && sawDefault && sawCharge
                    && violations.contains("neverDense"))) {
                JsonNode listed = browser.evaluate(VIOLATIONS);
                violations = listed == null ? violations : listed.asText();
                JsonNode running = browser.evaluate("Array.from(document.querySelectorAll('#tree g.status-running'))"
                        + ".map(g=>g.dataset.id).join(',')");
                if (running != null && !running.asText().isEmpty()) {
                    runningSets.add(running.asText());
                }
                JsonNode preparation = browser.evaluate(PREPARATION + "?" + PREPARATION + ".textContent:''");
                String value = preparation == null ? "" : preparation.asText();
                if (value.equals("none")) {
                    JsonNode inactive = browser.evaluate(CHARGE_FIRST + ".contains('inactive')");
                    sawDefault |= inactive != null && inactive.asBoolean();
                } else if (value.equals("charge") && sawDefault) {
                    JsonNode active = browser.evaluate(CHARGE_FIRST + ".contains('active')&&!" + CHARGE_FIRST
                            + ".contains('inactive')");
                    sawCharge |= active != null && active.asBoolean();
                }
                Thread.sleep(50);
            }
            assertTrue("running nodes seen: " + runningSets, runningSets.size() >= 3);
            assertTrue("ChargeFirst dimmed while preparation = none", sawDefault);
            assertTrue("ChargeFirst outlined once preparation = charge", sawCharge);
            assertTrue("violations listed: " + violations, violations.contains("neverDense")
                    && violations.contains("violated: qos.crowding = DENSE"));
            assertEquals(demo.errors(), 0, demo.await(TIMEOUT_MS));
        }
    }
}
