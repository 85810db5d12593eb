package org.miron.cli.monitor;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.function.UnaryOperator;
import org.miron.runtime.Json;
import org.miron.runtime.bus.Topics;
import org.miron.runtime.recording.BusLogReader.BusEvent;
import org.miron.runtime.recording.RecordedTree;
import org.miron.runtime.recording.Recording;

/**
 * What the live page showed at any instant of a recording: the recording's transitions (node
 * statuses, by the page's node ids) and its bus log (varpoints, metrics, requirement events) merged
 * in time order and told, up to that instant, to a fresh {@link MonitorState}, the live page's own
 * state (one mechanism, live or replayed); beside it the last decision taken by then. The
 * adaptations (decisions that changed a varpoint) are the slider's marks. Times are milliseconds
 * since the recording started.
 */
public final class ReplayState {
    /** One thing that happened, at {@code micros} since the start: a bus message as the live page gets it. */
    private record Step(long micros, String topic, JsonNode message) {
    }

    private final RecordedTree tree;
    private final List<Step> steps = new ArrayList<>();
    private final UnaryOperator<String> metricName;
    private final long durationMicros;

    public ReplayState(Recording recording, RecordedTree tree, List<BusEvent> bus, UnaryOperator<String> metricName) {
        this.tree = tree;
        this.metricName = metricName;
        long seq = 0;
        for (Recording.Transition t : recording.transitions()) {
            RecordedTree.RecordedNode node = tree.node(t.uid());
            if (node == null) {
                continue; // a uid the header does not have: nothing on the page to colour
            }
            ObjectNode status = Json.MAPPER.createObjectNode().put("tree", tree.mainTreeId()).put("node", node.path())
                    .put("to", t.status().name()).put("seq", ++seq);
            steps.add(new Step(t.micros(), Topics.BT_STATUS, status));
        }
        for (BusEvent e : bus) {
            // the statuses are the recording's; a tree message would clear them
            if (!e.topic().equals(Topics.BT_STATUS) && !e.topic().equals(Topics.BT_TREE)) {
                steps.add(new Step(Math.max(0, e.timeUs() - recording.startMicros()), e.topic(), e.message()));
            }
        }
        steps.sort(Comparator.comparingLong(Step::micros)); // stable: a transition before a bus message of the same instant
        durationMicros = steps.isEmpty() ? 0 : steps.get(steps.size() - 1).micros();
    }

    /** Milliseconds from the start to the last thing recorded. */
    public long durationMillis() {
        return (durationMicros + 999) / 1000;
    }

    /**
     * The page's state at {@code atMillis} (MonitorState's snapshot: tree, statuses, varpoints,
     * metrics, requirements), with {@code at} and {@code decision}, the last decision by then
     * ({@code miron.decision}'s body, null before the first).
     */
    public ObjectNode snapshot(long atMillis) {
        long at = atMillis * 1000;
        MonitorState state = new MonitorState(metricName);
        state.onBus(Topics.BT_TREE, Json.MAPPER.createObjectNode().put("tree", tree.mainTreeId()).toString()
                .getBytes(StandardCharsets.UTF_8));
        JsonNode decision = null;
        for (Step step : steps) {
            if (step.micros() > at) {
                break;
            }
            state.onBus(step.topic(), step.message().toString().getBytes(StandardCharsets.UTF_8));
            if (step.topic().equals(Topics.DECISION)) {
                decision = step.message();
            }
        }
        ObjectNode snapshot = state.snapshot();
        snapshot.put("at", atMillis);
        snapshot.set("decision", decision == null ? null : decision.deepCopy());
        return snapshot;
    }

    /**
     * The adaptations, the slider's marks: [{"at": ms, "seq", "changed": {vp: value}}], in time
     * order, each at the first millisecond whose snapshot has it.
     */
    public ArrayNode marks() {
        ArrayNode marks = Json.MAPPER.createArrayNode();
        for (Step step : steps) {
            if (step.topic().equals(Topics.DECISION) && step.message().path("changed").size() > 0) {
                // the first millisecond that shows it: a seek to the mark shows the decision
                ObjectNode mark = marks.addObject().put("at", (step.micros() + 999) / 1000).put("seq", step.message().path("seq").asLong());
                ObjectNode changed = mark.putObject("changed");
                step.message().path("changed").forEach(vp -> changed.set(vp.asText(), step.message().path("decisions").path(vp.asText())));
            }
        }
        return marks;
    }
}
