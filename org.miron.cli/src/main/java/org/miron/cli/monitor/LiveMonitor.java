package org.miron.cli.monitor;

import java.io.IOException;
import java.nio.file.Path;
import java.util.function.UnaryOperator;

import org.eclipse.emf.ecore.resource.Resource;
import org.miron.diagram.BtShapes;
import org.miron.diagram.Diagram;
import org.miron.diagram.Diagrams;
import org.miron.diagram.VariantHighlight;
import org.miron.generator.standalone.ModelLoader;
import org.miron.runtime.Endpoints;
import org.miron.runtime.Json;

/** Starts the live monitor of a tree file for {@code miron execute --monitor} and {@code miron demo --monitor}. */
public final class LiveMonitor {
    private LiveMonitor() {
    }

    /**
     * Draws the tree the executor will run (its main tree, expanded as it runs) and serves its page
     * on 127.0.0.1:{@code port}, following the bus of {@code endpoints}.
     */
    public static MonitorServer start(int port, Path treeFile, Endpoints endpoints, UnaryOperator<String> metricName)
            throws IOException {
        Resource resource = new ModelLoader().load(treeFile.toFile());
        Diagram diagram = BtShapes.expanded(resource, null);
        String svg = Diagrams.svg(diagram);
        String title = "MIRoN live: " + treeFile.getFileName();
        String switches = Json.MAPPER.writeValueAsString(VariantHighlight.switches(diagram));
        return new MonitorServer(port, MonitorPage.html(title, svg, switches), endpoints.busIn(), endpoints.busOut(),
                metricName);
    }

    /** Metrics named as they come: namespace/name → name. */
    public static UnaryOperator<String> plainNames() {
        return qualified -> qualified.substring(qualified.indexOf('/') + 1);
    }
}
