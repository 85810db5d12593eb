package org.miron.cli.demo;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.miron.runtime.sim.Comparison;
import org.miron.runtime.sim.CoverageTable;
import org.miron.runtime.sim.Simulation;
import org.miron.runtime.sim.Statistics;
import org.miron.runtime.sim.WorldModel;

/**
 * The page {@code miron simulate} writes: per measure a bar chart of the policies' means with their
 * 95 % bootstrap intervals (Statistics), then for the first run of each policy the demo report's timeline
 * (metrics, observations, contexts with the running skill, decisions, adaptations).
 */
public final class SimulationReport {
    private static final String[] COLORS = { "#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b" };
    private final String title;
    private final List<Comparison.PolicyRuns> results;
    private final WorldModel world;
    private final long timelineMs;

    public SimulationReport(String title, List<Comparison.PolicyRuns> results, WorldModel world, long timelineMs) {
        this.title = title;
        this.results = results;
        this.world = world;
        this.timelineMs = timelineMs;
    }

    private List<CoverageTable.Column> coverage;

    /** Adds the coverage section (null: none). */
    public SimulationReport coverage(List<CoverageTable.Column> columns) {
        this.coverage = columns;
        return this;
    }

    public Path write(Path file) throws IOException {
        return TimelineReport.writePage(file, html());
    }

    String html() {
        StringBuilder out = new StringBuilder();
        out.append(TimelineReport.pageHead("MIRoN simulation: " + title, ".bars{display:flex;flex-wrap:wrap;gap:1em}" + CoverageSection.STYLE))
                .append("<h1>MIRoN simulation: ").append(TimelineReport.escape(title)).append("</h1>\n");
        int runs = results.isEmpty() ? 0 : results.get(0).runs().size();
        out.append("<p>").append(runs).append(" run(s) per policy; bars are means, whiskers the " + Statistics.INTERVAL + ".</p>\n");
        out.append("<h2>Measures</h2>\n<div class=\"bars\">\n");
        for (String m : Comparison.measureNames(results)) {
            out.append(bars(m));
        }
        out.append("</div>\n");
        out.append(CoverageSection.html(coverage));
        for (Comparison.PolicyRuns r : results) {
            Simulation.Result first = r.runs().get(0);
            out.append("<h2>Policy ").append(TimelineReport.escape(r.policy().name())).append(": the first ")
                    .append(Math.round(timelineMs / 60000.0)).append(" min of run 1</h2>\n");
            out.append(new TimelineReport(r.policy().name(), TimelineReport.events(first.timeline()), timelineMs).body());
        }
        return out.append("</body></html>\n").toString();
    }

    private String bars(String measure) {
        int width = 300;
        int height = 190;
        int top = 30;
        int bottom = height - 40;
        List<Statistics.Summary> s = new ArrayList<>();
        double max = 0;
        double min = 0;
        for (Comparison.PolicyRuns r : results) {
            Statistics.Summary x = Statistics.of(Comparison.values(r, measure));
            s.add(x);
            if (Double.isFinite(x.hi())) {
                max = Math.max(max, x.hi());
                min = Math.min(min, x.lo());
            }
        }
        if (max == min) {
            max = min + 1;
        }
        String unit = world.measures().stream().filter(m -> m.name().equals(measure)).map(m -> m.unit()
                + (m.better().isEmpty() ? "" : (m.unit().isEmpty() ? "" : ", ") + m.better() + " is better")).findFirst().orElse("");
        StringBuilder svg = new StringBuilder(String.format(Locale.ROOT,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\">\n", width, height, width, height));
        svg.append(String.format(Locale.ROOT, "<text x=\"4\" y=\"14\" font-weight=\"bold\">%s</text>\n", TimelineReport.escape(measure
                + (unit.isEmpty() ? "" : " (" + unit + ")"))));
        int n = Math.max(1, s.size());
        double slot = (width - 20.0) / n;
        double range = max - min;
        for (int i = 0; i < s.size(); i++) {
            Statistics.Summary x = s.get(i);
            double zero = top + (bottom - top) * (max - 0) / range;
            double y = top + (bottom - top) * (max - x.mean()) / range;
            double cx = 10 + slot * i + slot / 2;
            String color = COLORS[i % COLORS.length];
            svg.append(String.format(Locale.ROOT, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"%s\" fill-opacity=\"0.6\">"
                    + "<title>%s: %s [%s, %s]</title></rect>\n", cx - slot * 0.3, Math.min(y, zero), slot * 0.6, Math.abs(zero - y), color,
                    TimelineReport.escape(results.get(i).policy().name()), num(x.mean()), num(x.lo()), num(x.hi())));
            double lo = top + (bottom - top) * (max - x.lo()) / range;
            double hi = top + (bottom - top) * (max - x.hi()) / range;
            svg.append(String.format(Locale.ROOT, "<line x1=\"%.1f\" x2=\"%.1f\" y1=\"%.1f\" y2=\"%.1f\" stroke=\"#222\"/>"
                    + "<line x1=\"%.1f\" x2=\"%.1f\" y1=\"%.1f\" y2=\"%.1f\" stroke=\"#222\"/><line x1=\"%.1f\" x2=\"%.1f\" y1=\"%.1f\" y2=\"%.1f\" stroke=\"#222\"/>\n",
                    cx, cx, lo, hi, cx - 6, cx + 6, lo, lo, cx - 6, cx + 6, hi, hi));
            svg.append(String.format(Locale.ROOT, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">%s</text>\n", cx, Math.min(y, zero) - 4,
                    num(x.mean())));
            String label = results.get(i).policy().name();
            svg.append(String.format(Locale.ROOT, "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\" fill=\"%s\">%s</text>\n", cx, height - 22,
                    color, TimelineReport.escape(label.length() > 22 ? label.substring(0, 21) + "…" : label)));
        }
        double zero = top + (bottom - top) * max / range;
        svg.append(String.format(Locale.ROOT, "<line x1=\"6\" x2=\"%d\" y1=\"%.1f\" y2=\"%.1f\" stroke=\"#444\"/>\n", width - 6, zero, zero));
        return svg.append("</svg>\n").toString();
    }

    private static String num(double v) {
        if (!Double.isFinite(v)) {
            return String.valueOf(v);
        }
        double a = Math.abs(v);
        return String.format(Locale.ROOT, a >= 100 || v == Math.rint(v) ? "%.0f" : a >= 10 ? "%.1f" : "%.3f", v);
    }
}
