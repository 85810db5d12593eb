package org.miron.cli.demo;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import org.miron.runtime.bus.Topics;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * What the robot did: one lane per skill action of the tree (by its node path), a bar from the
 * moment the executor started it to its result (green success, red failure, grey halted), from the
 * executor's {@code miron.bt.status} messages.
 */
final class SkillTimeline {
    private static final int WIDTH = 960;
    private static final int LEFT = 230;
    private static final int RIGHT = 20;
    private static final int LANE = 22;

    /** One run of a skill: start, end (ms), how it ended. */
    record Run(long from, long to, String result) {
    }

    private final Map<String, List<Run>> lanes = new LinkedHashMap<>();
    private final long end;

    SkillTimeline(List<BusRecorder.Event> events, long end) {
        this.end = Math.max(1, end);
        Map<String, Long> started = new LinkedHashMap<>();
        for (BusRecorder.Event e : events) {
            JsonNode body = e.body();
            if (!e.topic().equals(Topics.BT_STATUS) || !body.path("kind").asText().equals("skill")) {
                continue;
            }
            String lane = shortPath(body.path("path").asText());
            String to = body.path("to").asText();
            if (to.equals("RUNNING")) {
                started.put(lane, e.at());
            } else if (started.containsKey(lane) && (to.equals("SUCCESS") || to.equals("FAILURE") || to.equals("IDLE"))) {
                lanes.computeIfAbsent(lane, k -> new ArrayList<>())
                        .add(new Run(started.remove(lane), e.at(), to.equals("IDLE") ? "HALTED" : to));
            }
        }
        started.forEach((lane, from) -> lanes.computeIfAbsent(lane, k -> new ArrayList<>()).add(new Run(from, this.end, "RUNNING")));
    }

    /** The path without the tree's name and the weaver's monitoring nodes: what a person recognises. */
    static String shortPath(String path) {
        String[] parts = path.split("/");
        StringBuilder out = new StringBuilder();
        for (int i = 1; i < parts.length; i++) {
            if (!parts[i].startsWith("monitoring_")) {
                out.append(out.length() == 0 ? "" : "/").append(parts[i]);
            }
        }
        String text = out.length() == 0 ? path : out.toString();
        return text.length() <= 32 ? text : "…" + text.substring(text.length() - 31);
    }

    boolean isEmpty() {
        return lanes.isEmpty();
    }

    String html() {
        int height = lanes.size() * LANE + 30;
        StringBuilder svg = new StringBuilder(String.format(Locale.ROOT,
                "<h2>Skills</h2>\n<p>What the robot did: each skill the executor pushed, from its start to its result "
                        + "(green success, red failure, grey halted, blue still running).</p>\n"
                        + "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\">\n",
                WIDTH, height, WIDTH, height));
        int row = 0;
        for (Map.Entry<String, List<Run>> lane : lanes.entrySet()) {
            int top = row++ * LANE;
            svg.append(String.format(Locale.ROOT, "<text x=\"%d\" y=\"%d\" text-anchor=\"end\">%s</text>\n", LEFT - 8, top + 15,
                    TimelineReport.escape(lane.getKey())));
            for (Run run : lane.getValue()) {
                String fill = switch (run.result()) {
                    case "SUCCESS" -> "#16a34a";
                    case "FAILURE" -> "#dc2626";
                    case "RUNNING" -> "#2563eb";
                    default -> "#9ca3af";
                };
                svg.append(String.format(Locale.ROOT, "<rect class=\"skill-run\" x=\"%.1f\" y=\"%d\" width=\"%.1f\" height=\"%d\" "
                        + "fill=\"%s\"><title>%s: %.1f–%.1f s %s</title></rect>\n", x(run.from()), top + 4,
                        Math.max(1.5, x(run.to()) - x(run.from())), LANE - 8, fill, TimelineReport.escape(lane.getKey()),
                        run.from() / 1000.0, run.to() / 1000.0, run.result()));
            }
        }
        svg.append(String.format(Locale.ROOT, "<line x1=\"%d\" y1=\"%d\" x2=\"%d\" y2=\"%d\" stroke=\"#444\"/>\n", LEFT,
                lanes.size() * LANE + 2, WIDTH - RIGHT, lanes.size() * LANE + 2));
        long step = Math.max(1000, (end / 10 / 1000) * 1000);
        for (long t = 0; t <= end; t += step) {
            svg.append(String.format(Locale.ROOT, "<text x=\"%.1f\" y=\"%d\" text-anchor=\"middle\">%.1f s</text>\n", x(t),
                    lanes.size() * LANE + 18, t / 1000.0));
        }
        return svg.append("</svg>\n").toString();
    }

    private double x(long at) {
        return LEFT + (WIDTH - LEFT - RIGHT) * (double) Math.min(at, end) / end;
    }
}
