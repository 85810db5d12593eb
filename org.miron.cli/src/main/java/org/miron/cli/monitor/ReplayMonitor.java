package org.miron.cli.monitor;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.UnaryOperator;
import org.eclipse.emf.ecore.resource.Resource;
import org.miron.diagram.BtShapes;
import org.miron.diagram.Diagram;
import org.miron.diagram.Diagrams;
import org.miron.diagram.VariantHighlight;
import org.miron.generator.standalone.ModelLoader;
import org.miron.runtime.Json;
import org.miron.runtime.recording.RecordedTree;

/**
 * Starts the live page over a recording for {@code miron replay --monitor}: the tree drawn from
 * the recording's own header (whoever recorded it, no tree file needed), numbered as the live page
 * numbers it, and {@link ReplayServer} serving it with the slider of {@link ReplayPage}.
 */
public final class ReplayMonitor {
    private ReplayMonitor() {
    }

    public static ReplayServer start(int port, String title, RecordedTree tree, ReplayState replay) throws IOException {
        Path dir = Files.createTempDirectory("miron-replay");
        Path file = dir.resolve(tree.mainTreeId() + ".ext.xml"); // a woven tree: drawn with the weaver's node kinds
        try {
            Files.writeString(file, tree.loadableXml(), StandardCharsets.UTF_8);
            Resource resource = new ModelLoader().load(file.toFile());
            Diagram diagram = BtShapes.expanded(resource, null);
            String switches = Json.MAPPER.writeValueAsString(VariantHighlight.switches(diagram));
            String live = MonitorPage.html(title, Diagrams.svg(diagram), switches);
            return new ReplayServer(port, ReplayPage.html(live, replay.durationMillis(), replay.marks().toString()), replay);
        } finally {
            Files.deleteIfExists(file);
            Files.deleteIfExists(dir);
        }
    }

    /** Metrics named as they come: namespace/name → name. */
    public static UnaryOperator<String> plainNames() {
        return LiveMonitor.plainNames();
    }
}
