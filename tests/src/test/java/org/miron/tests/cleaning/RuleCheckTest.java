package org.miron.tests.cleaning;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.junit.Test;
import org.miron.cli.MironCli;
import picocli.CommandLine;

/**
 * `miron check` on the cleaning robot and its variants: conflicts of two and of three rules with a
 * witness situation and the winner, a rule that never applies, a rule always overridden. Each
 * warning is on the line of the rule it is about (the lower rule of a conflict).
 */
public class RuleCheckTest {

    /** The warnings `miron check` prints for a model (it exits 0: warnings only). */
    private static List<String> warnings(String model) {
        StringWriter out = new StringWriter();
        CommandLine cli = MironCli.commandLine();
        cli.setOut(new PrintWriter(out, true));
        cli.setErr(new PrintWriter(new StringWriter(), true));
        int exit = cli.execute("check", CleaningRobotTest.MODELS.resolve(model + ".miron").toString());
        assertEquals(out.toString(), 0, exit);
        return Arrays.stream(out.toString().split("\\R")).filter(l -> l.contains(": warning [")).toList();
    }

    /** "/file:line:column: warning" of the declaration of a rule (check prints paths relative to the working directory). */
    private static String at(String model, String rule) throws Exception {
        Path file = CleaningRobotTest.MODELS.resolve(model + ".miron");
        List<String> lines = Files.readAllLines(file);
        for (int i = 0; i < lines.size(); i++) {
            if (lines.get(i).startsWith("rule " + rule + " ")) {
                return "/" + model + ".miron:" + (i + 1) + ":6: warning"; // the rule's name, after "rule "
            }
        }
        throw new AssertionError("no rule " + rule + " in " + model);
    }

    @Test
    public void theIssuesConflictIsFoundWithAWitnessAndItsWinner() throws Exception {
        List<String> w = warnings("cleaning");
        assertEquals(w.toString(), 1, w.size());
        assertTrue(w.get(0), w.get(0).contains(at("cleaning", "filthy")));
        assertTrue(w.get(0), w.get(0).endsWith("warning [miron.rule-conflict]: rules battery and filthy conflict when "
                + "energy < 0.3, cleanliness < 0.3 and occupancy = EMPTY; battery wins"));
    }

    @Test
    public void threeRulesThatOnlyConflictTogether() throws Exception {
        List<String> w = warnings("three");
        assertEquals(w.toString(), 1, w.size());
        assertTrue(w.get(0), w.get(0).contains(at("three", "audit")));
        assertTrue(w.get(0), w.get(0).endsWith("[miron.rule-conflict]: rules battery, visitors and audit conflict when "
                + "energy < 0.3, occupancy = FEW and cleanliness < 0.2; battery and visitors win"));
    }

    @Test
    public void aRuleThatNeverApplies() throws Exception {
        List<String> w = warnings("never");
        assertEquals(w.toString(), 1, w.size());
        assertTrue(w.get(0), w.get(0).contains(at("never", "impossible")));
        assertTrue(w.get(0), w.get(0).contains("warning [miron.rule-never-applies]: rule impossible never applies"));
    }

    @Test
    public void aRuleAlwaysOverriddenByAHigherOne() throws Exception {
        List<String> w = warnings("shadowed");
        assertEquals(w.toString(), 1, w.size());
        assertTrue(w.get(0), w.get(0).contains(at("shadowed", "lowdeep")));
        assertTrue(w.get(0), w.get(0).contains("warning [miron.rule-shadowed]: rule lowdeep is always overridden by battery"));
    }

    @Test
    public void rulesThatHoldTogetherGetNoWarning() throws Exception {
        assertEquals(List.of(), warnings("initial"));
    }
}
