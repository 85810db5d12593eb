package org.miron.cli.demo;

import com.fasterxml.jackson.databind.JsonNode;
import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.miron.executor.Node;
import org.miron.executor.NodeStatus;
import org.miron.executor.skills.SkillActionNode;
import org.miron.executor.trace.StatusListener;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.engine.Binding;
import org.miron.runtime.engine.IoModel;
import org.miron.runtime.engine.VariationPoint;

/**
 * Tells on the console, as it happens, what the demo's robot perceives (RoQME inputs), what the
 * engine decides and why, and which skills the robot runs: one line per event, time first.
 */
final class Narrator implements StatusListener {
    private final PrintWriter out;
    private final IoModel model;
    private volatile BusRecorder clock;
    private final RoqmeNarration roqme = new RoqmeNarration(this::say);

    Narrator(PrintWriter out, IoModel model) {
        this.out = out;
        this.model = model;
    }

    void setClock(BusRecorder recorder) {
        clock = recorder;
    }

    void onBusEvent(BusRecorder.Event e) {
        JsonNode body = e.body();
        if (roqme.onEvent(e)) {
            return; // contexts, fired observations and the metrics they move (RoqmeNarration)
        } else if (e.topic().equals(Topics.DECISION)) {
            for (JsonNode changed : body.path("changed")) {
                String vp = changed.asText();
                say(e.at(), "ADAPT ", vp + " -> " + body.path("decisions").path(vp).asText() + where(vp)
                        + why(body, vp));
            }
        } else if (e.topic().equals(Topics.STATUS) && body.path("state").asText().equals("degraded")) {
            say(e.at(), "ENGINE", "degraded: " + body.path("lastError").path("message").asText()
                    + " (last good configuration kept)");
        }
    }

    /** Where a decision goes, from the varpoint's binding. */
    private String where(String varpoint) {
        VariationPoint vp = model.varpoint(varpoint).orElse(null);
        if (vp == null || vp.binding() == null) {
            return "";
        }
        Binding b = vp.binding();
        return switch (b.type()) {
            case "bt" -> " (behaviour tree switches branch)";
            case "arch" -> " (change-parameter " + b.text("component") + " " + b.text("parameter") + ")";
            case "btport" -> " (blackboard {" + varpoint + "})";
            default -> "";
        };
    }

    /** The engine's explanation (miron.decision's why, docs/wire-formats.md), else the metrics. */
    private static String why(JsonNode decision, String vp) {
        JsonNode because = decision.path("why").path(vp).path("because");
        String dropped = decision.path("dropped").isEmpty() ? ""
                : "; dropped " + String.join(", ", textsOf(decision.path("dropped")));
        return because.isTextual() ? ": " + because.asText() + dropped : "   (" + because(decision.path("inputs")) + ")";
    }

    private static List<String> textsOf(JsonNode array) {
        List<String> texts = new ArrayList<>();
        array.forEach(x -> texts.add(x.asText()));
        return texts;
    }

    private static String because(JsonNode inputs) {
        List<String> parts = new ArrayList<>();
        inputs.fields().forEachRemaining(f -> {
            if (f.getKey().startsWith("metric_")) {
                parts.add(shortName(f.getKey()) + "=" + fmt(f.getValue().asDouble()));
            }
        });
        return String.join(", ", parts);
    }

    /**
     * metric_Intralogistics_power_autonomy → power_autonomy, context_Hospital_shift → shift
     * (namespaces have no underscore): the model's names for the engine's MiniZinc parameters.
     */
    static String shortName(String param) {
        String rest = param.substring(param.indexOf('_') + 1);
        int underscore = rest.indexOf('_');
        return underscore > 0 && Character.isUpperCase(rest.charAt(0)) ? rest.substring(underscore + 1) : rest;
    }

    @Override
    public void statusChanged(long timeMillis, Node node, NodeStatus from, NodeStatus to) {
        if (node instanceof SkillActionNode && to == NodeStatus.RUNNING && from == NodeStatus.IDLE) {
            say(elapsed(), "ROBOT ", node.name() + inAttributes(node));
        }
    }

    private static String inAttributes(Node node) {
        List<String> parts = new ArrayList<>();
        node.ports().attributes().forEach((port, raw) -> {
            if (!port.equals("ID") && !port.equals("name")) {
                parts.add(port + "=" + node.ports().get(port).map(String::valueOf).orElse(raw));
            }
        });
        return parts.isEmpty() ? "" : " " + String.join(" ", parts);
    }

    private long elapsed() {
        return clock == null ? 0 : clock.elapsed();
    }

    void say(long at, String who, String what) {
        synchronized (out) {
            out.printf(Locale.ROOT, "%6.1f s  %s  %s%n", at / 1000.0, who, what);
            out.flush();
        }
    }

    private static String fmt(double v) {
        return String.format(Locale.ROOT, "%.2f", v);
    }
}
