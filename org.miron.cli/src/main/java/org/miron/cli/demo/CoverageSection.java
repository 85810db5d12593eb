package org.miron.cli.demo;

import java.util.List;
import java.util.Locale;

import org.miron.runtime.sim.Coverage;
import org.miron.runtime.sim.CoverageTable;

/**
 * The reports' coverage section (`--coverage`): a table with a row per tree node, variant and rule
 * and a column per policy, uncovered cells marked. A table, not the tree drawing: the simulate and
 * verify reports draw no trees.
 */
final class CoverageSection {
    static final String STYLE = ".uncovered{background:#fde0dc}td.num{text-align:right}";

    private CoverageSection() {
    }

    /** The section, or "" without coverage. */
    static String html(List<CoverageTable.Column> columns) {
        if (columns == null || columns.isEmpty()) {
            return "";
        }
        StringBuilder out = new StringBuilder("<h2>Coverage</h2>\n<p>Over all runs of each policy: a node's share of the "
                + "missions that ran it (its executions, SUCCESS and FAILURE endings), a variant's share of the time in force, "
                + "a rule's share of the decisions that applied it. Red: never ran, never in force, never applied.</p>\n"
                + "<table><tr><th>kind</th><th>item</th>");
        for (CoverageTable.Column c : columns) {
            out.append("<th>").append(TimelineReport.escape(c.policy())).append("</th>");
        }
        out.append("</tr>\n");
        List<Coverage.Item> items = columns.get(0).coverage().items();
        for (int i = 0; i < items.size(); i++) {
            out.append("<tr><td>").append(items.get(i).kind().name().toLowerCase(Locale.ROOT)).append("</td><td><code>")
                    .append(TimelineReport.escape(items.get(i).name())).append("</code></td>");
            for (CoverageTable.Column c : columns) {
                Coverage cov = c.coverage();
                Coverage.Item it = cov.items().get(i);
                out.append("<td class=\"num").append(it.covered() ? "" : " uncovered").append("\">")
                        .append(String.format(Locale.ROOT, "%.1f %%", 100 * it.share()));
                if (i < cov.nodes().size()) {
                    out.append(String.format(Locale.ROOT, " (%d: %d S, %d F)", cov.ticked(i), cov.succeeded(i), cov.failed(i)));
                }
                out.append("</td>");
            }
            out.append("</tr>\n");
        }
        out.append("<tr><th></th><th>covered</th>");
        for (CoverageTable.Column c : columns) {
            out.append(String.format(Locale.ROOT, "<th>%d of %d (%.1f %%)</th>", c.coverage().covered(), c.coverage().size(),
                    100 * c.coverage().coveredShare()));
        }
        return out.append("</tr>\n</table>\n").toString();
    }
}
