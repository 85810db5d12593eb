package org.miron.cli;

import static org.junit.Assert.assertEquals;

import java.io.IOException;
import java.nio.file.Path;
import org.junit.Rule;
import org.junit.Test;
import org.junit.rules.TemporaryFolder;

/**
 * `miron check` on requirements (docs/requirements.md): errors as file:line:col: error [code],
 * requirements the declared ranges make trivial or unsatisfiable, and rules whose conditions lie
 * outside a context's declared range.
 */
public class RequirementCheckCommandTest {
    @Rule
    public TemporaryFolder temp = new TemporaryFolder();

    private static final String ROQME = "roqme Tank\ncontext tankLevel : number (0:100)\ncontext open : boolean\n"
            + "property safety\n";
    private static final String VARPOINT = "import \"tank.roqme\" as q\n"
            + "@varpoint pump : number (0:1:3) in arch { parameterSetRepository \"R\" parameterSet \"S\" component \"C\" parameter \"p\" }\n";

    private String check(int exit, String miron) throws IOException {
        Path dir = temp.getRoot().toPath();
        Cli.write(dir, "tank.roqme", ROQME);
        Path file = Cli.write(dir, "tank.miron", VARPOINT + miron);
        Cli cli = new Cli();
        assertEquals(cli.out() + cli.err, exit, cli.run("check", file.toString()));
        return cli.out().replace(file.toString(), "tank.miron");
    }

    @Test
    public void badRequirementsAreErrorsWithTheirCodes() throws IOException {
        assertEquals("tank.miron:3:24: error [miron.requirement-type]: the state formula 'q.tankLevel' of requirement "
                + "'a' must be boolean, not number\n"
                + "tank.miron:4:35: error [miron.requirement-bound]: the bound of 'eventually within' must be at least "
                + "1 millisecond, not 0 seconds\n"
                + "tank.miron:5:62: error [miron.requirement-probability]: the probability of requirement 'c' must lie "
                + "strictly between 0 and 1, not 1.5 (a requirement every run must meet has no 'with probability')\n"
                + "tank.miron:6:24: error [miron.requirement-unknown-name]: unknown variable 'q.level'\n"
                + "tank.miron:7:10: error [miron.requirement-temporal-outside]: 'always' is a temporal operator: it is only "
                + "allowed in a requirement\n"
                + "tank.miron:8:35: error [miron.requirement-bound]: the bound of 'eventually within' must be at least "
                + "1 millisecond, not -2 minutes\n"
                + "tank.miron:9:32: error [miron.requirement-type]: cannot compare 'pump' (number) with 'q.open' (boolean) "
                + "using '='\n",
                check(1, "requirement a : always q.tankLevel\n"
                        + "requirement b : eventually within 0 seconds q.open\n"
                        + "requirement c : always q.tankLevel <= 50 with probability >= 1.5\n"
                        + "requirement d : always q.level > 1\n"
                        + "rule e : always q.open implies pump = 1\n"
                        + "requirement f : eventually within -2 minutes q.open\n"
                        + "requirement g : always (pump = q.open)\n"));
    }

    @Test
    public void requirementsTheRangesDecideAreWarnings() throws IOException {
        assertEquals("tank.miron:3:13: warning [miron.requirement-trivial]: requirement bounded can never be violated: "
                + "given the declared ranges and values, no run breaks it\n"
                + "tank.miron:4:13: warning [miron.requirement-unsatisfiable]: requirement overflow can never be met: "
                + "given the declared ranges and values, no run satisfies it\n"
                + "tank.miron:5:13: warning [miron.requirement-trivial]: requirement pumps can never be violated: "
                + "given the declared ranges and values, no run breaks it\n"
                + "tank.miron:6:13: warning [miron.requirement-unsatisfiable]: requirement estimate can never be met: "
                + "given the declared ranges and values, no run satisfies it\n",
                check(0, "requirement bounded : always q.tankLevel <= 100\n"
                        + "requirement overflow : eventually within 5 seconds q.tankLevel > 200\n"
                        + "requirement pumps : always (q.open implies pump <= 3)\n"
                        + "requirement estimate : eventually (q.safety > 1 and q.open)\n"
                        // decidable either way: no warning
                        + "requirement fine : always (q.tankLevel > 90 implies eventually within 1 minute pump = 0)\n"
                        + "requirement rare : never (q.tankLevel < 1 and not q.open) with probability >= 0.9\n"
                        // arithmetic over an input: not decided, no warning
                        + "requirement computed : always q.tankLevel * 2 <= 200\n"));
    }

    @Test
    public void aRuleBeyondTheDeclaredRangeNeverApplies() throws IOException {
        assertEquals("tank.miron:3:6: warning [miron.rule-never-applies]: rule overflowing never applies: its condition "
                + "is false in every situation (2 tried)\n",
                check(0, "rule overflowing : q.tankLevel > 100 implies pump = 0\n"
                        + "rule full : q.tankLevel >= 100 implies pump = 1\n"));
    }
}
