package org.miron.lsp.diagram;

import java.util.HashMap;
import java.util.Map;
import java.util.Set;

import org.eclipse.sprotty.SGraph;
import org.eclipse.xtext.resource.XtextResource;
import org.miron.diagram.Diagram;
import org.miron.diagram.DiagramLayout;
import org.miron.diagram.Diagrams;
import org.miron.diagram.Shape;
import org.miron.diagram.SourceSpan;

/** The laid-out diagram of one loaded file, with where each node is written. */
public final class DiagramGeneration {
    /**
     * A generated diagram. {@code parsed} false: the text has syntax errors and the model was not
     * drawn (the server keeps the last one).
     */
    public record Generated(SGraph root, Map<String, SourceSpan> spans, boolean parsed) {
    }

    private DiagramGeneration() {
    }

    public static Generated of(XtextResource resource, Set<String> expandedCalls) {
        if (resource.getParseResult() == null || resource.getParseResult().hasSyntaxErrors()) {
            return new Generated(null, Map.of(), false);
        }
        Diagram diagram = Diagrams.of(resource, null, expandedCalls);
        Map<String, SourceSpan> spans = new HashMap<>();
        for (Shape shape : diagram.shapes()) {
            if (shape.span() != null) {
                spans.put(shape.id(), shape.span());
            }
        }
        return new Generated(DiagramLayout.layout(diagram), spans, true);
    }
}
