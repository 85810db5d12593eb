package org.miron.cli.demo;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The report's "Requirements" section, from the {@code miron.requirement} events and the last
 * {@code miron.requirement.status} (docs/wire-formats.md): one lane per requirement with a red mark
 * at each violation and a red band while it lasted, each verdict over the run, and a table of the
 * violations with the values at their instant.
 */
final class RequirementLane {
    /** One violation: when (axis ms), when it was known, until when (met again; -1: not met again), values. */
    private record Violation(long at, long known, long until, String values) {
    }

    private final Map<String, List<Violation>> violations = new LinkedHashMap<>();
    private final Map<String, String> verdicts = new LinkedHashMap<>();
    private final TimelineReport axis;

    /** {@code scale}: axis ms per ms of the monitors' clock (the demo's time scale). */
    RequirementLane(List<BusRecorder.Event> events, JsonNode status, double scale, TimelineReport axis) {
        this.axis = axis;
        if (status != null) {
            status.path("requirements").fields().forEachRemaining(r -> {
                violations.computeIfAbsent(r.getKey(), k -> new ArrayList<>());
                verdicts.put(r.getKey(), r.getValue().path("verdict").asText());
            });
        }
        for (BusRecorder.Event e : events) {
            JsonNode b = e.body();
            String name = b.path("name").asText();
            if (name.isEmpty()) {
                continue;
            }
            List<Violation> list = violations.computeIfAbsent(name, k -> new ArrayList<>());
            long at = Math.round(b.path("time").asDouble() * 1000 * scale);
            if (b.path("verdict").asText().equals("violated")) {
                list.add(new Violation(at, Math.round(b.path("detected").asDouble() * 1000 * scale), -1, values(b.path("values"))));
            } else if (!list.isEmpty() && list.get(list.size() - 1).until() < 0) {
                Violation v = list.remove(list.size() - 1);
                list.add(new Violation(v.at(), v.known(), at, v.values()));
            }
        }
    }

    private static String values(JsonNode values) {
        List<String> parts = new ArrayList<>();
        values.fields().forEachRemaining(f -> parts.add(f.getKey() + " = "
                + (f.getValue().isNull() ? "(no value)" : f.getValue().isTextual() ? f.getValue().asText() : f.getValue().toString())));
        return String.join(", ", parts);
    }

    String html() {
        StringBuilder out = new StringBuilder("<h2>Requirements</h2>\n<p>A red mark where a requirement was violated, "
                + "red while it stayed violated.</p>\n");
        int lane = 22;
        StringBuilder svg = TimelineReport.svgStart(violations.size() * lane + 30);
        int row = 0;
        for (Map.Entry<String, List<Violation>> r : violations.entrySet()) {
            int middle = row * lane + lane / 2 + 2;
            svg.append(TimelineReport.text(TimelineReport.LEFT - 8, middle + 4, "end", r.getKey(), "#222"));
            for (Violation v : r.getValue()) {
                if (v.until() >= 0 && v.until() < axis.from() || v.at() > axis.end()) {
                    continue; // outside the window
                }
                double x0 = axis.x(v.at());
                double x1 = axis.x(v.until() < 0 ? axis.end() : v.until());
                svg.append(String.format(Locale.ROOT, "<rect x=\"%.1f\" y=\"%d\" width=\"%.1f\" height=\"12\" fill=\"red\" "
                        + "fill-opacity=\"0.2\"/>\n", x0, middle - 6, Math.max(1, x1 - x0)));
                if (axis.inWindow(v.at())) {
                    svg.append(String.format(Locale.ROOT, "<circle class=\"violation\" cx=\"%.1f\" cy=\"%d\" r=\"5\" fill=\"red\">"
                            + "<title>%s</title></circle>\n", x0, middle, TimelineReport.escape(TimelineReport.seconds(v.at())
                                    + " s: " + r.getKey() + " violated: " + v.values())));
                }
            }
            row++;
        }
        axis.axes(svg, violations.size() * lane);
        out.append(svg).append("</svg>\n");
        if (!verdicts.isEmpty()) {
            out.append("<table><tr><th>requirement</th><th>verdict</th><th>violations</th></tr>\n");
            verdicts.forEach((name, verdict) -> out.append("<tr><td>").append(TimelineReport.escape(name)).append("</td><td>")
                    .append(TimelineReport.escape(verdict)).append("</td><td>").append(violations.get(name).size())
                    .append("</td></tr>\n"));
            out.append("</table>\n");
        }
        out.append("<h3>Violations</h3>\n<table><tr><th>requirement</th><th>violated at (s)</th><th>known at (s)</th>"
                + "<th>met again at (s)</th><th>values</th></tr>\n");
        violations.forEach((name, list) -> list.forEach(v -> out.append("<tr class=\"violation\"><td>")
                .append(TimelineReport.escape(name)).append("</td><td>").append(TimelineReport.seconds(v.at()))
                .append("</td><td>").append(TimelineReport.seconds(v.known())).append("</td><td>")
                .append(v.until() < 0 ? "" : TimelineReport.seconds(v.until())).append("</td><td>")
                .append(TimelineReport.escape(v.values())).append("</td></tr>\n")));
        return out.append("</table>\n").toString();
    }
}
