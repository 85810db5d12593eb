package org.miron.diagram;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.util.BtTrees;
import org.miron.dsl.bt.BtXPath;
import org.miron.dsl.miron.ArchBinding;
import org.miron.dsl.miron.BehaviorTreeLiteral;
import org.miron.dsl.miron.BtBinding;
import org.miron.dsl.miron.MironModel;
import org.miron.dsl.miron.VariationPoint;
import org.miron.dsl.roqme.EnumLiteral;
import org.miron.dsl.roqme.EnumType;
import org.miron.dsl.roqme.Import;
import org.miron.dsl.roqme.Variable;
import org.miron.dsl.util.Imports;

/**
 * The shapes of a MIRoN model: the nominal trees of the BT files it imports ({@link BtShapes}),
 * each node a variation point is bound to highlighted, with a varpoint node below it that says how
 * ({@code in}, {@code before}, {@code after}) and holds one node per variant (linked to the tree it
 * puts in place, or "preset"); a varpoint bound to ports marks those ports with its name. Varpoints
 * bound to the architecture (or to nothing) are listed in a frame of their own.
 */
public final class MironShapes {
    private MironShapes() {
    }

    public static Diagram of(Resource miron) {
        Diagram diagram = new Diagram(miron.getURI().lastSegment());
        if (miron.getContents().isEmpty() || !(miron.getContents().get(0) instanceof MironModel model)) {
            return diagram;
        }
        Map<EObject, Shape> shapes = new java.util.HashMap<>();
        for (Resource bt : btFiles(model)) {
            BtShapes.Indexed nominal = BtShapes.definitions(bt);
            diagram.frames().addAll(nominal.diagram().frames());
            diagram.links().addAll(nominal.diagram().links());
            shapes.putAll(nominal.shapes());
        }
        Frame parameters = new Frame("parameters", "parameters (" + model.eResource().getURI().lastSegment() + ")");
        for (Variable variable : model.getVariables()) {
            if (variable instanceof VariationPoint vp) {
                if (vp.getBinding() instanceof BtBinding binding) {
                    bind(vp, binding, shapes, diagram);
                } else {
                    parameters.roots().add(parameter(vp));
                }
            }
        }
        if (!parameters.roots().isEmpty()) {
            diagram.frames().add(parameters);
        }
        return diagram;
    }

    /** The BT files a model imports, each once. */
    private static List<Resource> btFiles(MironModel model) {
        Set<Resource> files = new LinkedHashSet<>();
        for (Import imp : model.getImports()) {
            Resource r = Imports.load(imp);
            if (r != null && !r.getContents().isEmpty() && r.getContents().get(0) instanceof BTModel) {
                files.add(r);
            }
        }
        return new ArrayList<>(files);
    }

    private static void bind(VariationPoint vp, BtBinding binding, Map<EObject, Shape> shapes, Diagram diagram) {
        String insertion = binding.getInsertionType().getLiteral();
        for (EObject target : targets(binding)) {
            Shape node = shapes.get(target instanceof Attribute ? target.eContainer() : target);
            if (node == null) {
                continue;
            }
            if (target instanceof Attribute attribute) {
                node.cssClasses().add("varpoint-target");
                List<Shape.Port> ports = node.ports();
                for (int i = 0; i < ports.size(); i++) {
                    if (ports.get(i).name().equals(attribute.getName())) {
                        ports.set(i, new Shape.Port(ports.get(i).name(), ports.get(i).value(), vp.getName()));
                    }
                }
            } else if (target instanceof TreeNode) {
                node.cssClasses().add("varpoint-target");
                node.notes().add("◆ " + vp.getName() + " (" + insertion + ")");
                Shape point = new Shape(node.id() + "/" + vp.getName(), ShapeKind.VARPOINT, "◆ " + vp.getName(),
                        insertion + " " + node.title()).edgeType("edge:varpoint").span(SourceSpan.of(vp));
                for (EnumLiteral literal : literals(vp)) {
                    point.children().add(variant(point, literal, diagram, frameOf(diagram, node)));
                }
                node.children().add(point);
            }
        }
    }

    private static Shape variant(Shape point, EnumLiteral literal, Diagram diagram, String fromFrame) {
        String name = literal.getName();
        if (literal instanceof BehaviorTreeLiteral bt && !bt.isPreset() && bt.getReference() != null
                && !bt.getReference().eIsProxy()) {
            String tree = BtTrees.runName(bt.getReference());
            String frame = BtShapes.frameId(tree);
            if (fromFrame != null && diagram.frame(frame).isPresent()) {
                diagram.links().add(new Diagram.Link(fromFrame, frame, "edge:variant"));
            }
            return new Shape(point.id() + "/" + name, ShapeKind.VARIANT, name, "→ " + tree).link(frame)
                    .edgeType("edge:variant").span(SourceSpan.of(literal));
        }
        return new Shape(point.id() + "/" + name, ShapeKind.VARIANT, name, "preset: the nominal tree")
                .edgeType("edge:variant").span(SourceSpan.of(literal));
    }

    private static List<EnumLiteral> literals(VariationPoint vp) {
        return vp.getDeclaration() instanceof EnumType type ? type.getLiterals() : List.of();
    }

    private static String frameOf(Diagram diagram, Shape node) {
        return diagram.frames().stream().filter(f -> f.shapes().contains(node)).map(Frame::id).findFirst().orElse(null);
    }

    /** The nodes and ports a binding selects: its targets, or what its XPath selects below each. */
    private static List<EObject> targets(BtBinding binding) {
        List<EObject> result = new ArrayList<>();
        for (TreeNode target : binding.getTargets()) {
            if (target == null || target.eIsProxy()) {
                continue;
            }
            if (binding.getXpath() == null) {
                result.add(target);
                continue;
            }
            for (BtXPath.Selection s : BtXPath.evaluate(binding.getXpath(), target).selections) {
                if (s.model instanceof TreeNode || s.model instanceof Attribute) {
                    result.add(s.model);
                }
            }
        }
        return result;
    }

    private static Shape parameter(VariationPoint vp) {
        String where = vp.getBinding() instanceof ArchBinding arch
                ? "arch " + arch.getComponent() + "." + arch.getParameter() : "not bound";
        Shape shape = new Shape("parameters/" + vp.getName(), ShapeKind.VARPOINT, "◆ " + vp.getName(), where)
                .span(SourceSpan.of(vp));
        for (EnumLiteral literal : literals(vp)) {
            shape.notes().add(literal.getName());
        }
        return shape;
    }
}
