package org.miron.diagram;

import java.util.Set;

import org.eclipse.emf.ecore.resource.Resource;
import org.eclipse.sprotty.SGraph;
import org.miron.dsl.miron.MironModel;

/** The entry points: the diagram of a loaded model file, laid out, as an SVG. */
public final class Diagrams {
    private Diagrams() {
    }

    /**
     * The diagram of a BT file (.bt, .xml, woven .ext.xml) or a MIRoN model; {@code treeId} non-null
     * keeps that tree's frame only. Null when the tree is not in the diagram.
     */
    public static Diagram of(Resource resource, String treeId) {
        return of(resource, treeId, Set.of());
    }

    /** {@link #of(Resource, String)} with the SubTree calls whose node ids are given expanded (BT files). */
    public static Diagram of(Resource resource, String treeId, Set<String> expandedCalls) {
        boolean miron = !resource.getContents().isEmpty() && resource.getContents().get(0) instanceof MironModel;
        Diagram diagram = miron ? MironShapes.of(resource) : BtShapes.of(resource, expandedCalls);
        if (treeId == null) {
            return diagram;
        }
        String id = BtShapes.frameId(treeId);
        if (diagram.frame(id).isEmpty()) {
            return null;
        }
        Diagram one = new Diagram(diagram.title());
        one.frames().add(diagram.frame(id).get());
        return one;
    }

    public static SGraph layout(Diagram diagram) {
        return DiagramLayout.layout(diagram);
    }

    public static String svg(Diagram diagram) {
        return SvgWriter.write(DiagramLayout.layout(diagram));
    }
}
