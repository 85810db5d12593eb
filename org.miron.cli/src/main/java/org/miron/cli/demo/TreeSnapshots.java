package org.miron.cli.demo;

import java.io.IOException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.sprotty.SGraph;
import org.miron.diagram.BtShapes;
import org.miron.diagram.Diagram;
import org.miron.diagram.DiagramLayout;
import org.miron.diagram.SvgWriter;
import org.miron.diagram.VariantHighlight;
import org.miron.generator.standalone.ModelLoader;
import org.miron.runtime.Json;
import org.miron.runtime.bus.Topics;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * The report's behaviour-tree section: the woven tree as it runs (org.miron.diagram), drawn once at
 * the start and again after every adaptation that switched a variant, the active branch of each
 * variant Switch outlined and the others dimmed. One layout serves every picture.
 */
final class TreeSnapshots {
    /** At most this many pictures: a long run keeps its first adaptations. */
    private static final int MAX = 12;

    private final Diagram diagram;
    private final SGraph graph;
    /** A varpoint to the blackboard key its Switches read (io.json binding.variable). */
    private final Map<String, String> keys = new LinkedHashMap<>();

    private TreeSnapshots(Diagram diagram, Map<String, String> keys) {
        this.diagram = diagram;
        this.graph = DiagramLayout.layout(diagram);
        this.keys.putAll(keys);
    }

    /** The snapshots of a woven tree with its io.json; null when the files cannot be read (the report goes on without). */
    static TreeSnapshots of(Path tree, Path ioJson) {
        try {
            Resource resource = new ModelLoader().load(tree.toFile());
            Map<String, String> keys = new LinkedHashMap<>();
            for (JsonNode vp : Json.MAPPER.readTree(ioJson.toFile()).path("varpoints")) {
                JsonNode binding = vp.path("binding");
                if (binding.path("type").asText().equals("bt") && binding.hasNonNull("variable")) {
                    keys.put(vp.path("name").asText(), binding.path("variable").asText());
                }
            }
            return new TreeSnapshots(BtShapes.expanded(resource, null), keys);
        } catch (IOException | RuntimeException e) {
            return null;
        }
    }

    /** The section: a picture before the first decision and after each decision that switched a variant. */
    String html(List<BusRecorder.Event> events) {
        StringBuilder out = new StringBuilder("<h2>Behaviour tree</h2>\n<p>The woven tree as the executor runs it; in each "
                + "variant Switch the branch of the current decision is outlined in green and the others are dimmed.</p>\n");
        Map<String, String> values = new LinkedHashMap<>();
        int shown = 0;
        out.append(picture("before the first decision", values));
        for (BusRecorder.Event e : events) {
            if (!e.topic().equals(Topics.DECISION) || shown >= MAX) {
                continue;
            }
            StringBuilder switched = new StringBuilder();
            for (JsonNode changed : e.body().path("changed")) {
                String vp = changed.asText();
                if (keys.containsKey(vp)) {
                    String value = e.body().path("decisions").path(vp).asText();
                    values.put(keys.get(vp), value);
                    switched.append(switched.length() == 0 ? "" : ", ").append(vp).append(" → ").append(value);
                }
            }
            if (switched.length() > 0) {
                out.append(picture(String.format(java.util.Locale.ROOT, "%.1f s: %s", e.at() / 1000.0, switched), values));
                shown++;
            }
        }
        return out.toString();
    }

    private String picture(String caption, Map<String, String> values) {
        return "<figure><figcaption>" + TimelineReport.escape(caption) + "</figcaption>\n"
                + SvgWriter.write(graph, VariantHighlight.classes(diagram, values)) + "</figure>\n";
    }
}
