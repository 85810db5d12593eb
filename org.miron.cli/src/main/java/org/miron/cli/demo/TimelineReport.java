package org.miron.cli.demo;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.miron.cli.ModelNames;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.sim.TimelineEvent;

/**
 * A self-contained HTML page (inline SVG, no scripts) that shows why the robot adapted: the QoS
 * metrics (the provider's estimate curves, with a mark where an observation fired), the fired
 * observations, the contexts and the engine's decisions on one time axis, and a table of every
 * adaptation with the inputs the engine saw when it made it.
 */
public final class TimelineReport {
    static final int WIDTH = 960;
    static final int LEFT = 150;
    private static final int RIGHT = 20;
    private static final String[] COLORS = { "#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b",
            "#e377c2", "#17becf" };

    /** A value of one series at a time (ms). */
    record Point(long at, JsonNode value) {
    }

    private final String title;
    /** The window drawn, in ms of the events' time axis: [from, end]. */
    private final long from;
    private final long end;
    private final Map<String, List<Point>> metrics = new LinkedHashMap<>();
    private final Map<String, List<Point>> contexts = new LinkedHashMap<>();
    private final Map<String, List<Point>> decisions = new LinkedHashMap<>();
    private final List<String[]> adaptations = new ArrayList<>();
    private final List<Long> problems = new ArrayList<>();
    /** Fired observations by name: when, and what each did ("undermines safety (HIGH)"). */
    private final Map<String, List<Long>> observations = new LinkedHashMap<>();
    private final Map<String, String> observationEffects = new LinkedHashMap<>();
    /** Event contexts (eventtype) by name: when each occurred. */
    private final Map<String, List<Long>> eventContexts = new LinkedHashMap<>();

    /** miron.requirement events and the last miron.requirement.status (RequirementLane). */
    private final List<BusRecorder.Event> requirementEvents = new ArrayList<>();
    private JsonNode requirementStatus;
    private double requirementTimeScale = 1.0;

    /** More sections, after the decisions: the tree pictures, the skills. */
    private final List<String> sections = new ArrayList<>();
    private final ModelNames names;

    public TimelineReport(String title, List<BusRecorder.Event> events, long end) {
        this(title, events, end, ModelNames.none());
    }

    /** A report naming the inputs as the model does ({@code roqme.safety}). */
    public TimelineReport(String title, List<BusRecorder.Event> events, long end, ModelNames names) {
        this(title, events, 0, end, names, false);
    }

    /**
     * A report of the window {@code [fromMs, endMs]} only (axis labels in absolute seconds, curves
     * and lanes clipped to it, the adaptations in it): a counterexample's timeline around its violation.
     */
    public TimelineReport(String title, List<BusRecorder.Event> events, long fromMs, long endMs, ModelNames names) {
        this(title, events, fromMs, endMs, names, true);
    }

    private TimelineReport(String title, List<BusRecorder.Event> events, long fromMs, long endMs, ModelNames names,
            boolean window) {
        this.title = title;
        this.names = names;
        this.from = Math.max(0, fromMs);
        this.end = Math.max(this.from + 1, endMs);
        Map<String, String> applied = new LinkedHashMap<>();
        for (BusRecorder.Event e : events) {
            JsonNode body = e.body();
            if (e.topic().equals(Topics.REQUIREMENT)) {
                requirementEvents.add(e);
            } else if (e.topic().equals(Topics.REQUIREMENT_STATUS)) {
                requirementStatus = body;
            } else if (e.topic().equals(Topics.ESTIMATE)) {
                add(metrics, body.path("name").asText(), e.at(), body.path("value"));
            } else if (e.topic().equals(Topics.OBSERVATION)) {
                String name = body.path("name").asText();
                observations.computeIfAbsent(name, k -> new ArrayList<>()).add(e.at());
                observationEffects.computeIfAbsent(name, k -> effects(body.path("actions")));
            } else if (e.topic().equals(Topics.CONTEXT) && body.path("type").asText().equals("event")) {
                eventContexts.computeIfAbsent(body.path("name").asText(), k -> new ArrayList<>()).add(e.at());
            } else if (e.topic().equals(Topics.CONTEXT)) {
                add(contexts, body.path("name").asText(), e.at(), body.path("value"));
            } else if (e.topic().equals(Topics.DECISION)) {
                body.path("decisions").fields().forEachRemaining(d -> add(decisions, d.getKey(), e.at(), d.getValue()));
                for (JsonNode changed : body.path("changed")) {
                    String vp = changed.asText();
                    String now = body.path("decisions").path(vp).asText();
                    if (!window || inWindow(e.at())) {
                        adaptations.add(new String[] { seconds(e.at()), vp, applied.getOrDefault(vp, "(start)"), now,
                                body.path("why").path(vp).path("because").asText(""), inputsOf(body.path("inputs"), names) });
                    }
                    applied.put(vp, now);
                }
            } else if (e.topic().equals(Topics.STATUS) && body.path("state").asText().equals("degraded")) {
                problems.add(e.at());
            }
        }
        if (window) {
            clip();
        }
    }

    long from() {
        return from;
    }

    long end() {
        return end;
    }

    boolean inWindow(long at) {
        return at >= from && at <= end;
    }

    /** Keeps what lies in the window; a series' value at its start is the last one before it. */
    private void clip() {
        for (Map<String, List<Point>> series : List.of(metrics, contexts, decisions)) {
            series.replaceAll((name, points) -> clipped(points));
            series.values().removeIf(List::isEmpty);
        }
        for (Map<String, List<Long>> dots : List.of(observations, eventContexts)) {
            dots.values().forEach(times -> times.removeIf(t -> !inWindow(t)));
            dots.values().removeIf(List::isEmpty);
        }
        observationEffects.keySet().retainAll(observations.keySet());
        problems.removeIf(t -> !inWindow(t));
    }

    private List<Point> clipped(List<Point> points) {
        List<Point> out = new ArrayList<>();
        Point before = null;
        for (Point p : points) {
            if (p.at() < from) {
                before = p;
            } else if (p.at() <= end) {
                out.add(p);
            }
        }
        if (before != null && (out.isEmpty() || out.get(0).at() > from)) {
            out.add(0, new Point(from, before.value()));
        }
        return out;
    }

    /**
     * The requirement events' times are in seconds of the monitors' clock; the axis is the events'
     * ({@code at}). The demo's monitors run on world time, its axis is wall time: {@code scale} is
     * its time scale (wall ms per world ms). Default 1.
     */
    public TimelineReport requirementTimeScale(double scale) {
        this.requirementTimeScale = scale;
        return this;
    }

    private static void add(Map<String, List<Point>> series, String name, long at, JsonNode value) {
        if (!name.isEmpty() && !value.isMissingNode()) {
            series.computeIfAbsent(name, k -> new ArrayList<>()).add(new Point(at, value));
        }
    }

    private static String effects(JsonNode actions) {
        List<String> parts = new ArrayList<>();
        for (JsonNode a : actions) {
            String target = a.path(a.has("belief") ? "belief" : a.has("var") ? "var" : "timer").asText();
            String strength = a.path("strength").asText("");
            parts.add(a.path("kind").asText() + " " + target + (strength.isEmpty() ? "" : " (" + strength + ")"));
        }
        return String.join(", ", parts);
    }

    private static String inputsOf(JsonNode inputs, ModelNames names) {
        List<String> parts = new ArrayList<>();
        inputs.fields().forEachRemaining(f -> {
            if (!f.getKey().endsWith("_known") && !f.getKey().contains("_input") && !f.getKey().endsWith("_current")) {
                JsonNode v = f.getValue();
                // In the model's names (roqme.safety, qos.shift), not the MiniZinc parameters'.
                String name = names.parameter(f.getKey());
                parts.add(name + " = " + (v.isFloatingPointNumber() ? fmt(v.asDouble()) : v.asText()));
            }
        });
        return String.join(", ", parts);
    }

    /** Adds a section (HTML) after the adaptations. */
    public TimelineReport section(String html) {
        if (html != null && !html.isEmpty()) {
            sections.add(html);
        }
        return this;
    }

    public Path write(Path file) throws IOException {
        return writePage(file, html());
    }

    /** Writes a report page (UTF-8), making its folder. */
    static Path writePage(Path file, String html) throws IOException {
        Files.createDirectories(file.toAbsolutePath().getParent());
        Files.writeString(file, html, StandardCharsets.UTF_8);
        return file;
    }

    /** A report page's start up to {@code <body>}: the reports' common style, then the page's own. */
    static String pageHead(String title, String style) {
        return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" + escape(title)
                + "</title>\n<style>body{font-family:sans-serif;margin:2em;color:#222}h2{margin-top:1.5em}"
                + "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:4px 8px;text-align:left;"
                + "font-size:13px}svg text{font-size:12px}" + style + "</style></head><body>\n";
    }

    /** A simulated run's timeline (the simulator records it, docs/simulator.md) as the events a report draws. */
    public static List<BusRecorder.Event> events(List<TimelineEvent> timeline) {
        List<BusRecorder.Event> events = new ArrayList<>();
        for (TimelineEvent e : timeline) {
            events.add(new BusRecorder.Event(e.at(), e.topic(), e.body()));
        }
        return events;
    }

    /** The report without its page head and title: a section of another page (simulation, verification). */
    String body() {
        String page = html();
        int from = page.indexOf("</h1>");
        int to = page.lastIndexOf("</body>");
        return from >= 0 && to > from ? page.substring(from + "</h1>".length(), to) : "";
    }

    String html() {
        StringBuilder out = new StringBuilder();
        out.append(pageHead(title, "figure{margin:1em 0;overflow-x:auto}figcaption{font-weight:bold;margin-bottom:.3em}"))
                .append("<h1>").append(escape(title)).append("</h1>\n<p>").append(adaptations.size())
                .append(" adaptations ").append(from == 0 ? "in " + seconds(end) : "from " + seconds(from) + " s to " + seconds(end))
                .append(" s")
                .append(problems.isEmpty() ? "" : ", " + problems.size() + " solver problems (red marks)").append(".</p>\n");
        out.append("<h2>QoS metrics</h2>\n<p>The estimates the engine received; a dotted line marks a fired "
                + "observation.</p>\n").append(lineChart(metrics, 0, 1));
        if (!observations.isEmpty()) {
            out.append("<h2>Observations fired</h2>\n").append(dotLanes(observations, name -> name + ": " + observationEffects.get(name)))
                    .append("<table><tr><th>observation</th><th>what it does</th><th>fired at (s)</th></tr>\n");
            observations.forEach((name, times) -> out.append("<tr><td>").append(escape(name)).append("</td><td>")
                    .append(escape(observationEffects.get(name))).append("</td><td>")
                    .append(String.join(", ", times.stream().map(TimelineReport::seconds).toList())).append("</td></tr>\n"));
            out.append("</table>\n");
        }
        if (!contexts.isEmpty() || !eventContexts.isEmpty()) {
            out.append("<h2>Contexts</h2>\n").append(lanes(contexts));
        }
        if (!eventContexts.isEmpty()) {
            out.append(dotLanes(eventContexts, name -> name + " occurred"));
        }
        out.append("<h2>Decisions</h2>\n").append(lanes(decisions));
        if (!requirementEvents.isEmpty() || requirementStatus != null) {
            out.append(new RequirementLane(requirementEvents, requirementStatus, requirementTimeScale, this).html());
        }
        out.append("<h2>Adaptations</h2>\n<table><tr><th>time (s)</th><th>variation point</th><th>from</th><th>to</th>"
                + "<th>why</th><th>inputs the engine saw</th></tr>\n");
        for (String[] row : adaptations) {
            out.append("<tr>");
            for (String cell : row) {
                out.append("<td>").append(escape(cell)).append("</td>");
            }
            out.append("</tr>\n");
        }
        out.append("</table>\n");
        sections.forEach(out::append);
        return out.append("</body></html>\n").toString();
    }

    /** Numeric series as step lines over a shared value axis. */
    private String lineChart(Map<String, List<Point>> series, double min, double max) {
        int height = 180;
        StringBuilder svg = svgStart(height + 30);
        axes(svg, height);
        svg.append(text(LEFT - 8, 14, "end", fmt(max))).append(text(LEFT - 8, height, "end", fmt(min)));
        int color = 0;
        for (Map.Entry<String, List<Point>> s : series.entrySet()) {
            String stroke = COLORS[color++ % COLORS.length];
            StringBuilder path = new StringBuilder();
            double lastY = -1;
            for (Point p : s.getValue()) {
                double y = 10 + (height - 10) * (1 - (p.value().asDouble() - min) / (max - min));
                double x = x(p.at());
                path.append(path.length() == 0 ? "M" : (" L" + fmt(x) + "," + fmt(lastY) + " L")).append(fmt(x)).append(',')
                        .append(fmt(y));
                lastY = y;
            }
            if (lastY >= 0) {
                path.append(" L").append(fmt(x(end))).append(',').append(fmt(lastY));
            }
            svg.append("<path d=\"").append(path).append("\" fill=\"none\" stroke=\"").append(stroke)
                    .append("\" stroke-width=\"2\"/>\n");
            svg.append(text(10, 20 + 16 * (color - 1), "start", s.getKey(), stroke));
        }
        observationMarks(svg, height);
        return problemMarks(svg, height).append("</svg>\n").toString();
    }

    /** A dotted grey line where any observation fired, under the curves' legend. */
    private void observationMarks(StringBuilder svg, int height) {
        observations.values().stream().flatMap(List::stream).distinct().forEach(at -> svg.append(String.format(Locale.ROOT,
                "<line x1=\"%.1f\" x2=\"%.1f\" y1=\"10\" y2=\"%d\" stroke=\"#999\" stroke-dasharray=\"2,3\"/>\n",
                x(at), x(at), height)));
    }

    /** One lane per name: a dot each time it occurred, with what it is (tooltip). */
    private String dotLanes(Map<String, List<Long>> occurrences, java.util.function.UnaryOperator<String> what) {
        int lane = 22;
        StringBuilder svg = svgStart(occurrences.size() * lane + 30);
        int row = 0;
        for (Map.Entry<String, List<Long>> o : occurrences.entrySet()) {
            int middle = row * lane + lane / 2 + 2;
            String color = COLORS[row % COLORS.length];
            svg.append(text(LEFT - 8, middle + 4, "end", o.getKey(), color));
            for (long at : o.getValue()) {
                svg.append(String.format(Locale.ROOT, "<circle cx=\"%.1f\" cy=\"%d\" r=\"4\" fill=\"%s\"><title>%s</title></circle>\n",
                        x(at), middle, color, escape(seconds(at) + " s: " + what.apply(o.getKey()))));
            }
            row++;
        }
        axes(svg, occurrences.size() * lane);
        return svg.append("</svg>\n").toString();
    }

    /** One lane per series: the value written in a band that lasts until the next value. */
    private String lanes(Map<String, List<Point>> series) {
        int lane = 28;
        StringBuilder svg = svgStart(series.size() * lane + 30);
        int row = 0;
        for (Map.Entry<String, List<Point>> s : series.entrySet()) {
            int top = row * lane;
            svg.append(text(LEFT - 8, top + 18, "end", s.getKey()));
            Map<String, String> colorOf = new LinkedHashMap<>();
            JsonNode previous = null;
            for (Point p : s.getValue()) {
                if (p.value().equals(previous)) {
                    continue; // the same value again: its band already runs to the next change
                }
                previous = p.value();
                String label = p.value().isNumber() ? fmt(p.value().asDouble()) : p.value().asText();
                long until = nextChange(s.getValue(), p);
                String fill = colorOf.computeIfAbsent(label, k -> COLORS[colorOf.size() % COLORS.length]);
                double width = Math.max(1, x(until) - x(p.at()));
                svg.append(String.format(Locale.ROOT,
                        "<rect x=\"%.1f\" y=\"%d\" width=\"%.1f\" height=\"%d\" fill=\"%s\" fill-opacity=\"0.25\" stroke=\"%s\">"
                                + "<title>%s</title></rect>\n",
                        x(p.at()), top + 4, width, lane - 6, fill, fill, escape(s.getKey() + " = " + label + " from " + seconds(p.at()) + " s")));
                String shown = fitted(label, width);
                if (!shown.isEmpty()) {
                    svg.append(text(x(p.at()) + 4, top + 18, "start", shown));
                }
            }
            row++;
        }
        axes(svg, series.size() * lane);
        return svg.append("</svg>\n").toString();
    }

    /** The label, shortened with an ellipsis to fit a band of that width (about 7 px a character), or "". */
    private static String fitted(String label, double width) {
        int chars = (int) ((width - 8) / 7);
        if (chars >= label.length()) {
            return label;
        }
        return chars >= 3 ? label.substring(0, chars - 1) + "…" : "";
    }

    /** When the value of {@code p} stops holding: the next point with another value, or the end. */
    private long nextChange(List<Point> points, Point p) {
        boolean after = false;
        for (Point q : points) {
            if (after && !q.value().equals(p.value())) {
                return q.at();
            }
            after |= q == p;
        }
        return end;
    }

    private StringBuilder problemMarks(StringBuilder svg, int height) {
        for (long at : problems) {
            svg.append(String.format(Locale.ROOT, "<line x1=\"%.1f\" x2=\"%.1f\" y1=\"0\" y2=\"%d\" stroke=\"red\"/>\n",
                    x(at), x(at), height));
        }
        return svg;
    }

    static StringBuilder svgStart(int height) {
        return new StringBuilder(String.format(Locale.ROOT,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\">\n", WIDTH,
                height, WIDTH, height));
    }

    void axes(StringBuilder svg, int height) {
        svg.append(String.format(Locale.ROOT, "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"#444\"/>\n", LEFT,
                height + 2, WIDTH - RIGHT, height + 2));
        long step = Math.max(1000, ((end - from) / 10 / 1000) * 1000);
        for (long t = (from + step - 1) / step * step; t <= end; t += step) {
            svg.append(text(x(t), height + 18, "middle", seconds(t) + " s"));
        }
    }

    double x(long at) {
        return LEFT + (WIDTH - LEFT - RIGHT) * (double) (Math.min(Math.max(at, from), end) - from) / (end - from);
    }

    private static String text(double x, double y, String anchor, String text) {
        return text(x, y, anchor, text, "#222");
    }

    static String text(double x, double y, String anchor, String text, String color) {
        return String.format(Locale.ROOT, "<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"%s\" fill=\"%s\">%s</text>\n", x, y,
                anchor, color, escape(text));
    }

    static String seconds(long ms) {
        return String.format(Locale.ROOT, "%.1f", ms / 1000.0);
    }

    private static String fmt(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e9 ? Long.toString((long) v) : String.format(Locale.ROOT, "%.2f", v);
    }

    static String escape(String text) {
        return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
