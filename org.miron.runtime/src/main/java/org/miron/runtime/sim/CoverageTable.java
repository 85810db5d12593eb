package org.miron.runtime.sim;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.miron.runtime.Json;

/**
 * The coverage of each policy's runs as the commands print and write it: a line per item with a
 * column per policy, the {@code coverage} object of {@code summary.json}, and the {@code --min-coverage} gate.
 */
public final class CoverageTable {
    /** One policy's name and its runs' coverage, merged. */
    public record Column(String policy, Coverage coverage) {
    }

    private CoverageTable() {
    }

    /** The policies' runs merged, a column each. */
    public static List<Column> of(List<Comparison.PolicyRuns> results) {
        List<Column> out = new ArrayList<>();
        for (Comparison.PolicyRuns r : results) {
            out.add(new Column(r.policy().name(), Coverage.merge(r.runs().stream().map(Simulation.Result::coverage).toList())));
        }
        return out;
    }

    /**
     * {@code kind  name  share [counts]} per item and policy, then the covered items per policy. The
     * share: of the missions that ran a node (its executions, SUCCESS and FAILURE endings), of the time
     * a variant was in force, of the decisions that applied a rule.
     */
    public static String table(List<Column> columns) {
        if (columns.isEmpty()) {
            return "";
        }
        Coverage shape = columns.get(0).coverage();
        List<Coverage.Item> items = shape.items();
        List<List<String>> cells = new ArrayList<>();
        int[] widths = new int[columns.size()];
        for (int c = 0; c < columns.size(); c++) {
            List<String> col = new ArrayList<>();
            Coverage cov = columns.get(c).coverage();
            List<Coverage.Item> its = cov.items();
            for (int i = 0; i < its.size(); i++) {
                col.add(cell(cov, its, i));
            }
            col.add(String.format(Locale.ROOT, "%d of %d (%.1f %%)", cov.covered(), cov.size(), 100 * cov.coveredShare()));
            widths[c] = Math.max(columns.get(c).policy().length(), col.stream().mapToInt(String::length).max().orElse(0));
            cells.add(col);
        }
        int name = Math.max("covered".length(), items.stream().mapToInt(i -> i.name().length()).max().orElse(0));
        String head = "%-8s  %-" + name + "s";
        StringBuilder b = new StringBuilder(String.format(Locale.ROOT, head, "coverage", "item"));
        for (int c = 0; c < columns.size(); c++) {
            b.append("  ").append(pad(columns.get(c).policy(), widths[c]));
        }
        trimEnd(b).append('\n');
        for (int i = 0; i <= items.size(); i++) {
            b.append(i < items.size() ? String.format(Locale.ROOT, head, kind(items.get(i).kind()), items.get(i).name())
                    : String.format(Locale.ROOT, head, "", "covered"));
            for (int c = 0; c < columns.size(); c++) {
                b.append("  ").append(pad(cells.get(c).get(i), widths[c]));
            }
            trimEnd(b).append('\n');
        }
        return b.toString();
    }

    private static String cell(Coverage cov, List<Coverage.Item> items, int i) {
        Coverage.Item it = items.get(i);
        String share = String.format(Locale.ROOT, "%5.1f %%", 100 * it.share());
        return switch (it.kind()) {
            case NODE -> share + String.format(Locale.ROOT, "  ticked %d, S %d, F %d", cov.ticked(i), cov.succeeded(i), cov.failed(i));
            case VARIANT -> share;
            case RULE -> {
                int r = i - cov.nodes().size() - cov.variants().size();
                yield share + String.format(Locale.ROOT, "  %d of %d decisions", cov.applied(r), cov.decisions());
            }
        };
    }

    private static String kind(Coverage.Kind k) {
        return k.name().toLowerCase(Locale.ROOT);
    }

    private static String pad(String s, int width) {
        return s + " ".repeat(Math.max(0, width - s.length()));
    }

    private static StringBuilder trimEnd(StringBuilder b) {
        int n = b.length();
        while (n > 0 && b.charAt(n - 1) == ' ') {
            n--;
        }
        b.setLength(n);
        return b;
    }

    /**
     * {@code {POLICY: {"items", "covered", "share", "missions", "decisions", "nodes": [{"path",
     * "ticked", "success", "failure", "missions", "share"}], "variants": [{"name", "heldS", "share"}],
     * "rules": [{"name", "applied", "share"}]}}}, six significant digits, in the model's order.
     */
    public static ObjectNode json(List<Column> columns) {
        ObjectNode root = Json.object();
        for (Column col : columns) {
            Coverage cov = col.coverage();
            ObjectNode p = root.putObject(col.policy());
            p.put("items", cov.size());
            p.put("covered", cov.covered());
            p.put("share", Comparison.round(cov.coveredShare()));
            p.put("missions", cov.missions());
            p.put("decisions", cov.decisions());
            List<Coverage.Item> items = cov.items();
            ArrayNode nodes = p.putArray("nodes");
            for (int i = 0; i < cov.nodes().size(); i++) {
                nodes.addObject().put("path", cov.nodes().get(i)).put("ticked", cov.ticked(i)).put("success", cov.succeeded(i))
                        .put("failure", cov.failed(i)).put("missions", cov.missionsWith(i))
                        .put("share", Comparison.round(items.get(i).share()));
            }
            ArrayNode variants = p.putArray("variants");
            int offset = cov.nodes().size();
            for (int i = 0; i < cov.variants().size(); i++) {
                variants.addObject().put("name", cov.variants().get(i)).put("heldS", cov.heldMs(i) / 1000.0)
                        .put("share", Comparison.round(items.get(offset + i).share()));
            }
            ArrayNode rules = p.putArray("rules");
            offset += cov.variants().size();
            for (int i = 0; i < cov.rules().size(); i++) {
                rules.addObject().put("name", cov.rules().get(i)).put("applied", cov.applied(i))
                        .put("share", Comparison.round(items.get(offset + i).share()));
            }
        }
        return root;
    }

    /** One line per policy whose covered share falls below {@code minPercent}; empty when all reach it. */
    public static List<String> belowMinimum(List<Column> columns, double minPercent) {
        List<String> out = new ArrayList<>();
        for (Column col : columns) {
            double pct = 100 * col.coverage().coveredShare();
            if (100.0 * col.coverage().covered() < minPercent * col.coverage().size()) { // exact: 23 of 25 is 92 %
                out.add(String.format(Locale.ROOT, "coverage of %s is %.1f %% (%d of %d items), below --min-coverage %s %%",
                        col.policy(), pct, col.coverage().covered(), col.coverage().size(), Comparison.fmt(minPercent)));
            }
        }
        return out;
    }
}
