package org.miron.cli;

import java.io.PrintWriter;
import java.util.List;

import org.miron.runtime.sim.CoverageTable;

import com.fasterxml.jackson.databind.node.ObjectNode;

/** What `--coverage` and `--min-coverage` add to `miron simulate` and `miron verify`: the table, the summary's object, the gate. */
final class CoverageOutput {
    private CoverageOutput() {
    }

    /** A usage error in the coverage options, or null. */
    static String check(SimulationOptions run) {
        if (run.minCoverage != null && !(run.minCoverage >= 0 && run.minCoverage <= 100)) {
            return "--min-coverage must lie in [0, 100], e.g. 80";
        }
        return null;
    }

    /** Prints the table and puts {@code coverage} into the summary; false when a policy falls short of --min-coverage (said on {@code err}). */
    static boolean report(SimulationOptions run, List<CoverageTable.Column> columns, PrintWriter console, PrintWriter err,
            String command, ObjectNode summary) {
        if (!run.coverage()) {
            return true;
        }
        console.println();
        console.print(CoverageTable.table(columns));
        console.println();
        console.println("(node: share of the missions that ran it, with its executions and SUCCESS/FAILURE endings; variant: share "
                + "of the time in force; rule: share of the decisions that applied it; covered: ran, in force or applied at least once)");
        summary.set("coverage", CoverageTable.json(columns));
        if (run.minCoverage == null) {
            return true;
        }
        List<String> falling = CoverageTable.belowMinimum(columns, run.minCoverage);
        for (String line : falling) {
            err.println("miron " + command + ": " + line);
        }
        err.flush();
        return falling.isEmpty();
    }
}
