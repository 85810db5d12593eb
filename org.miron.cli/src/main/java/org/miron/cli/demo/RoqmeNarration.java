package org.miron.cli.demo;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.miron.runtime.bus.Topics;

/**
 * The RoQME lines of the demo's console: what the robot perceives (contexts, when their value
 * changes), which observations fired and how they moved the metrics, and the metrics themselves
 * only when they change noticeably, so the console tells why without flooding. An observation's
 * evidence counts at the provider's next tick, so its line waits for the estimates of that tick:
 * {@code tooClose fired: undermines safety (high) → safety 0.70 → 0.41}.
 */
final class RoqmeNarration {
    /** A metric move smaller than this, without a fired observation behind it, is not told. */
    static final double NOTICEABLE = 0.1;

    /** Says a line: time (ms since the start), who, what. */
    interface Say {
        void say(long at, String who, String what);
    }

    /** An observation that fired, with the belief actions still waiting for their tick's estimate. */
    private record Firing(String name, Map<String, String> pending) {
    }

    private final Say out;
    private final List<Firing> firings = new ArrayList<>();
    private final Map<String, Double> told = new HashMap<>();
    private final Map<String, String> lastContext = new HashMap<>();

    RoqmeNarration(Say out) {
        this.out = out;
    }

    /** Tells a RoQME message; returns false when the topic is not a RoQME one it tells. */
    synchronized boolean onEvent(BusRecorder.Event e) {
        JsonNode body = e.body();
        String name = body.path("name").asText();
        switch (e.topic()) {
            case Topics.CONTEXT -> {
                JsonNode v = body.path("value");
                // a world's readings (49.3128...) told to one decimal, and only when that changes
                String value = v.isFloatingPointNumber() ? String.format(java.util.Locale.ROOT, "%.1f", v.asDouble()) : v.asText();
                if (!value.equals(lastContext.put(name, value)) || body.path("type").asText().equals("event")) {
                    out.say(e.at(), "RoQME ", name + " = " + value);
                }
            }
            case Topics.OBSERVATION -> observed(e.at(), name, body.path("actions"));
            case Topics.ESTIMATE -> estimated(e.at(), name, body.path("value").asDouble());
            default -> {
                return false;
            }
        }
        return true;
    }

    private void observed(long at, String name, JsonNode actions) {
        Map<String, String> pending = new LinkedHashMap<>();
        List<String> other = new ArrayList<>();
        for (JsonNode a : actions) {
            String kind = a.path("kind").asText();
            if (a.hasNonNull("belief")) {
                String strength = a.path("strength").asText("");
                String what = kind + " " + a.path("belief").asText()
                        + (strength.isEmpty() || strength.equals("MEDIUM") ? "" : " (" + strength.toLowerCase(Locale.ROOT) + ")");
                pending.merge(a.path("belief").asText(), what, (x, y) -> x + ", " + y);
            } else {
                other.add(kind + " " + a.path(a.has("var") ? "var" : "timer").asText());
            }
        }
        if (!other.isEmpty() || pending.isEmpty()) {
            out.say(at, "RoQME ", name + " fired" + (other.isEmpty() ? "" : ": " + String.join(", ", other)));
        }
        if (!pending.isEmpty()) {
            firings.add(new Firing(name, pending));
        }
    }

    private void estimated(long at, String property, double value) {
        List<String> causes = new ArrayList<>();
        for (Iterator<Firing> it = firings.iterator(); it.hasNext();) {
            Firing f = it.next();
            String what = f.pending().remove(property);
            if (what != null) {
                causes.add(f.name() + " fired: " + what);
            }
            if (f.pending().isEmpty()) {
                it.remove();
            }
        }
        Double before = told.get(property);
        if (!causes.isEmpty()) {
            boolean same = before != null && fmt(before).equals(fmt(value));
            out.say(at, "RoQME ", String.join("; ", causes) + (same ? " (" + property + " stays " + fmt(value) + ")"
                    : " → " + property + " " + (before == null ? "" : fmt(before) + " → ") + fmt(value)));
        } else if (before == null) {
            out.say(at, "RoQME ", property + " = " + fmt(value));
        } else if (Math.abs(value - before) >= NOTICEABLE) {
            out.say(at, "RoQME ", property + " " + fmt(before) + " → " + fmt(value));
        } else {
            return; // a small drift: the last told value stays the reference for the next move
        }
        told.put(property, value);
    }

    private static String fmt(double v) {
        return String.format(Locale.ROOT, "%.2f", v);
    }
}
