package org.miron.cli.demo;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.miron.cli.ModelNames;
import org.miron.runtime.requirement.RequirementEvent;
import org.miron.runtime.sim.CoverageTable;
import org.miron.runtime.sim.Setup;
import org.miron.runtime.sim.Simulation;
import org.miron.runtime.sim.Verification;

/**
 * The page {@code miron verify} writes: every requirement with its formula and, per policy, its
 * runs, violations, violation probability and verdict; then each first counterexample as the demo
 * report's timeline of the signals around the violation. The run is simulated again with the same
 * seed (the simulator is deterministic) recording only that window, so no run keeps a timeline it
 * may not need.
 */
public final class VerifyReport {
    /** How much of the run before and after the violating instant the timeline shows. */
    static final long BEFORE_MS = 60_000;
    static final long AFTER_MS = 30_000;

    private final String title;
    private final Setup setup;
    private final List<Verification.PolicyResult> results;
    private final Verification.Options options;
    private final ModelNames names;

    public VerifyReport(String title, Setup setup, List<Verification.PolicyResult> results, Verification.Options options,
            ModelNames names) {
        this.title = title;
        this.setup = setup;
        this.results = results;
        this.options = options;
        this.names = names;
    }

    private List<CoverageTable.Column> coverage;

    /** Adds the coverage section (null: none). */
    public VerifyReport coverage(List<CoverageTable.Column> columns) {
        this.coverage = columns;
        return this;
    }

    public Path write(Path file) throws IOException {
        return TimelineReport.writePage(file, html());
    }

    String html() {
        StringBuilder out = new StringBuilder();
        out.append(TimelineReport.pageHead("MIRoN verification: " + title, ".holds{color:#2ca02c}.violated,.fails{color:#d62728}"
                + ".undecided,.not-evaluated{color:#ff7f0e}code{font-size:13px}" + CoverageSection.STYLE))
                .append("<h1>MIRoN verification: ").append(TimelineReport.escape(title)).append("</h1>\n");
        out.append("<p>Each run is ").append(TimelineReport.escape(duration(options.durationMs())))
                .append(" of simulated time; P(violation) is the share of runs that violated the requirement with its exact 95 % "
                        + "interval (Clopper–Pearson); a probabilistic requirement is decided by Wald's sequential test.</p>\n");
        out.append("<h2>Requirements</h2>\n<table><tr><th>requirement</th><th>formula</th><th>policy</th><th>runs</th>"
                + "<th>violated</th><th>P(violation) [95 % CI]</th><th>verdict</th><th>first counterexample</th></tr>\n");
        for (Verification.PolicyResult r : results) {
            for (Verification.Check c : r.checks()) {
                out.append("<tr><td>").append(TimelineReport.escape(c.requirement().name())).append("</td><td><code>")
                        .append(TimelineReport.escape(c.requirement().text()
                                + (c.requirement().probability() == null ? "" : " with probability >= " + c.requirement().probability())))
                        .append("</code></td><td>").append(TimelineReport.escape(r.policy().name())).append("</td><td>").append(c.runs())
                        .append("</td><td>").append(c.violated()).append("</td><td>")
                        .append(String.format(Locale.ROOT, "%.3f [%.3f, %.3f]", c.interval().estimate(), c.interval().lo(), c.interval().hi()))
                        .append("</td><td class=\"").append(c.verdict()).append("\">").append(TimelineReport.escape(Verification.verdictText(c)))
                        .append("</td><td>").append(c.first() == null ? "" : "<a href=\"#" + anchor(c, r) + "\">run " + c.first().run()
                                + " at " + RequirementEvent.seconds(c.first().timeMs()) + " s</a>")
                        .append("</td></tr>\n");
            }
        }
        out.append("</table>\n");
        out.append(CoverageSection.html(coverage));
        for (Verification.PolicyResult r : results) {
            for (Verification.Check c : r.checks()) {
                if (c.first() != null) {
                    out.append(counterexample(r, c));
                }
            }
        }
        return out.append("</body></html>\n").toString();
    }

    private String counterexample(Verification.PolicyResult r, Verification.Check c) {
        Verification.Counterexample x = c.first();
        long from = Math.max(0, x.timeMs() - BEFORE_MS);
        long to = Math.min(options.durationMs(), Math.max(x.detectedMs(), x.timeMs()) + AFTER_MS);
        Simulation.Result again = new Simulation(setup, r.policy(), x.seed(), options.durationMs(), to).timelineWindow(from).run();
        String timeline = new TimelineReport(c.requirement().name(), TimelineReport.events(again.timeline()), from, to, names).body();
        return "<h2 id=\"" + anchor(c, r) + "\">" + TimelineReport.escape(c.requirement().name()) + " under "
                + TimelineReport.escape(r.policy().name()) + ": run " + x.run() + " (seed " + x.seed() + ") violated it at "
                + RequirementEvent.seconds(x.timeMs()) + " s</h2>\n<p><code>" + TimelineReport.escape(c.requirement().text())
                + "</code></p>\n<p>Values then: " + TimelineReport.escape(RequirementEvent.format(x.values()))
                + (x.detectedMs() > x.timeMs() ? "; known at " + RequirementEvent.seconds(x.detectedMs()) + " s" : "")
                + ". The timeline shows " + RequirementEvent.seconds(from) + " s to " + RequirementEvent.seconds(to) + " s.</p>\n"
                + timeline;
    }

    private static String anchor(Verification.Check c, Verification.PolicyResult r) {
        return ("cx-" + c.requirement().name() + "-" + r.policy().name()).replaceAll("[^A-Za-z0-9_-]", "_");
    }

    private static String duration(long ms) {
        return ms % 3_600_000 == 0 ? ms / 3_600_000 + " h" : ms % 60_000 == 0 ? ms / 60_000 + " min" : ms / 1000.0 + " s";
    }
}
