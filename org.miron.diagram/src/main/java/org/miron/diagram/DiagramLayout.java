package org.miron.diagram;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.elk.alg.layered.options.CrossingMinimizationStrategy;
import org.eclipse.elk.alg.layered.options.LayeringStrategy;
import org.eclipse.elk.alg.layered.options.LayeredMetaDataProvider;
import org.eclipse.elk.alg.layered.options.LayeredOptions;
import org.eclipse.elk.alg.layered.options.OrderingStrategy;
import org.eclipse.elk.core.RecursiveGraphLayoutEngine;
import org.eclipse.elk.core.data.LayoutMetaDataService;
import org.eclipse.elk.core.math.ElkPadding;
import org.eclipse.elk.core.math.KVector;
import org.eclipse.elk.core.options.CoreOptions;
import org.eclipse.elk.core.options.Direction;
import org.eclipse.elk.core.options.EdgeRouting;
import org.eclipse.elk.core.options.SizeConstraint;
import org.eclipse.elk.core.util.BasicProgressMonitor;
import org.eclipse.elk.graph.ElkBendPoint;
import org.eclipse.elk.graph.ElkEdge;
import org.eclipse.elk.graph.ElkEdgeSection;
import org.eclipse.elk.graph.ElkNode;
import org.eclipse.elk.graph.util.ElkGraphUtil;
import org.eclipse.sprotty.Dimension;
import org.eclipse.sprotty.Point;
import org.eclipse.sprotty.SEdge;
import org.eclipse.sprotty.SGraph;
import org.eclipse.sprotty.SLabel;
import org.eclipse.sprotty.SModelElement;
import org.eclipse.sprotty.SNode;

/**
 * Lays a {@link Diagram} out with ELK layered, top-down, and returns it as a Sprotty model: the
 * graph holds one {@code tree} node per frame (its heading a {@code label:heading}), each holding
 * its tree's {@code node:<kind>} nodes with {@code label:title}, {@code label:type},
 * {@code label:port} and {@code label:note} labels, and the {@code edge:child} edges from parent to
 * child; {@code edge:call} and {@code edge:variant} edges join the frames. Each frame is laid out
 * on its own (children in document order), then the frames with the edges between them. Positions
 * are relative to the parent, as Sprotty has them; edges carry ELK's route as routing points.
 */
public final class DiagramLayout {
    static {
        LayoutMetaDataService.getInstance().registerLayoutMetaDataProviders(new LayeredMetaDataProvider());
    }

    private DiagramLayout() {
    }

    public static SGraph layout(Diagram diagram) {
        ElkNode graph = ElkGraphUtil.createGraph();
        configure(graph, 40, 40);
        graph.setProperty(CoreOptions.PADDING, new ElkPadding(12));
        SGraph root = new SGraph();
        root.setType("graph");
        root.setId("graph");
        root.setChildren(new ArrayList<>());
        Map<String, ElkNode> frames = new HashMap<>();
        Map<ElkNode, SNode> nodes = new HashMap<>();
        List<Object[]> edges = new ArrayList<>(); // {ElkEdge, SEdge}
        for (Frame frame : diagram.frames()) {
            ElkNode box = ElkGraphUtil.createNode(graph);
            configure(box, 18, 32);
            inCreationOrder(box);
            box.setProperty(CoreOptions.PADDING, new ElkPadding(Metrics.HEADING + 8, 14, 14, 14));
            box.setProperty(CoreOptions.NODE_SIZE_CONSTRAINTS, EnumSet.of(SizeConstraint.MINIMUM_SIZE));
            box.setProperty(CoreOptions.NODE_SIZE_MINIMUM, new KVector(Metrics.headingWidth(frame.title()), Metrics.HEADING + 20));
            frames.put(frame.id(), box);
            SNode tree = node(frame.id(), "tree", new ArrayList<>(frame.cssClasses()));
            tree.getChildren().add(label(frame.id() + "#heading", "label:heading", frame.title(), Metrics.PAD_X, 8));
            nodes.put(box, tree);
            root.getChildren().add(tree);
            for (Shape shape : frame.roots()) {
                add(shape, null, box, tree, nodes, edges);
            }
        }
        for (Diagram.Link link : diagram.links()) {
            ElkNode from = frames.get(link.from());
            ElkNode to = frames.get(link.to());
            if (from != null && to != null && from != to) {
                SEdge edge = edge(link.from() + "->" + link.to() + "#" + link.type(), link.type(), link.from(), link.to());
                root.getChildren().add(edge);
                edges.add(new Object[] { connect(from, to), edge });
            }
        }
        new RecursiveGraphLayoutEngine().layout(graph, new BasicProgressMonitor());
        nodes.forEach((elk, sprotty) -> {
            sprotty.setPosition(new Point(elk.getX(), elk.getY()));
            sprotty.setSize(new Dimension(elk.getWidth(), elk.getHeight()));
        });
        for (Object[] pair : edges) {
            ((SEdge) pair[1]).setRoutingPoints(route((ElkEdge) pair[0]));
        }
        root.setSize(new Dimension(graph.getWidth(), graph.getHeight()));
        return root;
    }

    private static void configure(ElkNode node, double between, double layers) {
        node.setProperty(CoreOptions.ALGORITHM, LayeredOptions.ALGORITHM_ID);
        node.setProperty(CoreOptions.DIRECTION, Direction.DOWN);
        node.setProperty(LayeredOptions.SPACING_NODE_NODE, between);
        node.setProperty(LayeredOptions.SPACING_NODE_NODE_BETWEEN_LAYERS, layers);
        node.setProperty(LayeredOptions.EDGE_ROUTING, EdgeRouting.ORTHOGONAL);
        // A tree's children stay in the order the file writes them (it is their execution order).
        node.setProperty(LayeredOptions.CONSIDER_MODEL_ORDER_STRATEGY, OrderingStrategy.NODES_AND_EDGES);
        node.setProperty(LayeredOptions.CROSSING_MINIMIZATION_FORCE_NODE_MODEL_ORDER, true);
    }

    /**
     * A frame holds a forest whose nodes are created depth first: layered from the sources, each
     * node goes one layer below its parent in creation order, so every layer is already in document
     * order (a tree's execution order) without a crossing, and crossing minimisation is left out.
     * ELK's model-order sorting did the same at a cost cubic in a layer's width: most of a one-shot
     * render of a 459-node tree (docs/performance.md). The drawings are the same.
     */
    private static void inCreationOrder(ElkNode box) {
        box.setProperty(LayeredOptions.CONSIDER_MODEL_ORDER_STRATEGY, OrderingStrategy.NONE);
        box.setProperty(LayeredOptions.CROSSING_MINIMIZATION_FORCE_NODE_MODEL_ORDER, false);
        box.setProperty(LayeredOptions.CROSSING_MINIMIZATION_STRATEGY, CrossingMinimizationStrategy.NONE);
        box.setProperty(LayeredOptions.LAYERING_STRATEGY, LayeringStrategy.LONGEST_PATH_SOURCE);
    }

    private static void add(Shape shape, ElkNode parent, ElkNode box, SNode tree, Map<ElkNode, SNode> nodes,
            List<Object[]> edges) {
        ElkNode elk = ElkGraphUtil.createNode(box);
        double width = Metrics.width(shape);
        elk.setDimensions(width, Metrics.height(shape));
        List<String> css = new ArrayList<>(shape.cssClasses());
        TreeSNode node = (TreeSNode) node(shape.id(), shape.kind().type(), css);
        node.setTrace(shape.source());
        node.setLink(shape.link());
        node.setExpanded(shape.expanded());
        double y = Metrics.PAD_Y;
        node.getChildren().add(label(shape.id() + "#title", "label:title", shape.title(), Metrics.PAD_X, y));
        y += Metrics.LINE;
        node.getChildren().add(label(shape.id() + "#type", "label:type", shape.type(), Metrics.PAD_X, y));
        int i = 0;
        for (Shape.Port port : shape.ports()) {
            y += Metrics.LINE;
            String text = Metrics.lines(shape).get(i++);
            SLabel label = label(shape.id() + "#port" + i, "label:port", text, Metrics.PAD_X, y);
            if (port.parameter() != null) {
                label.setCssClasses(new ArrayList<>(List.of("parameter")));
            }
            node.getChildren().add(label);
        }
        for (String note : shape.notes()) {
            y += Metrics.LINE;
            node.getChildren().add(label(shape.id() + "#note" + (i++), "label:note", note, Metrics.PAD_X, y));
        }
        nodes.put(elk, node);
        tree.getChildren().add(node);
        if (parent != null) {
            SEdge edge = edge(nodes.get(parent).getId() + "->" + shape.id(), shape.edgeType(), nodes.get(parent).getId(),
                    shape.id());
            tree.getChildren().add(edge);
            edges.add(new Object[] { connect(parent, elk), edge });
        }
        for (Shape child : shape.children()) {
            add(child, elk, box, tree, nodes, edges);
        }
    }

    private static ElkEdge connect(ElkNode from, ElkNode to) {
        ElkEdge edge = ElkGraphUtil.createSimpleEdge(from, to);
        ElkGraphUtil.updateContainment(edge);
        return edge;
    }

    private static List<Point> route(ElkEdge edge) {
        List<Point> points = new ArrayList<>();
        if (edge.getSections().isEmpty()) {
            return points;
        }
        ElkEdgeSection section = edge.getSections().get(0);
        points.add(new Point(section.getStartX(), section.getStartY()));
        for (ElkBendPoint bend : section.getBendPoints()) {
            points.add(new Point(bend.getX(), bend.getY()));
        }
        points.add(new Point(section.getEndX(), section.getEndY()));
        return points;
    }

    private static SNode node(String id, String type, List<String> css) {
        SNode node = new TreeSNode();
        node.setId(id);
        node.setType(type);
        node.setCssClasses(css);
        node.setChildren(new ArrayList<>());
        return node;
    }

    private static SLabel label(String id, String type, String text, double x, double y) {
        SLabel label = new SLabel();
        label.setId(id);
        label.setType(type);
        label.setText(text);
        label.setPosition(new Point(x, y));
        return label;
    }

    private static SEdge edge(String id, String type, String source, String target) {
        SEdge edge = new SEdge();
        edge.setId(id);
        edge.setType(type);
        edge.setSourceId(source);
        edge.setTargetId(target);
        return edge;
    }

    /** Every element of a model, depth first (tests and writers walk it). */
    public static List<SModelElement> all(SModelElement root) {
        List<SModelElement> result = new ArrayList<>();
        collect(root, result);
        return result;
    }

    private static void collect(SModelElement element, List<SModelElement> into) {
        into.add(element);
        if (element.getChildren() != null) {
            element.getChildren().forEach(child -> collect(child, into));
        }
    }
}
