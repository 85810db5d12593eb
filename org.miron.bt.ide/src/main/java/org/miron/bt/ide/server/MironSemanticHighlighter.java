package org.miron.bt.ide.server;

import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.EAttribute;
import org.eclipse.emf.ecore.EClass;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.xtext.Keyword;
import org.eclipse.xtext.ide.editor.syntaxcoloring.IHighlightedPositionAcceptor;
import org.eclipse.xtext.ide.editor.syntaxcoloring.ISemanticHighlightingCalculator;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.ILeafNode;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.resource.XtextResource;
import org.eclipse.xtext.util.CancelIndicator;

/**
 * Semantic tokens (textDocument/semanticTokens) of the three languages, so that editors colour
 * what a name denotes, the same way in every file: a tree's name where it is declared, in a
 * SubTree's ID and after a MIRoN alias ({@code main.Charge}: namespace, class); RoQME properties,
 * contexts and observations wherever they are used (in MIRoN rules and impacts too); enum
 * literals; and each BT element by its kind (control, decorator, action, condition, subtree),
 * its closing tag too. Token types are LSP's standard ones (Xtext's legend).
 */
public class MironSemanticHighlighter implements ISemanticHighlightingCalculator {
    static final String DECLARATION = "declaration";
    private static final Map<String, String> TYPES = Map.ofEntries(
            Map.entry("bt.BehaviorTree", "class"), Map.entry("bt.SubtreeNode", "class"),
            Map.entry("bt.ControlNode", "keyword"), Map.entry("bt.DecoratorNode", "decorator"),
            Map.entry("bt.Condition", "method"), Map.entry("bt.LeafNode", "function"),
            Map.entry("bt.TreeNode", "function"), Map.entry("bt.Attribute", "property"),
            Map.entry("roqme.Property", "property"), Map.entry("roqme.BeliefVariable", "property"),
            Map.entry("roqme.Context", "variable"), Map.entry("roqme.Var", "variable"),
            Map.entry("roqme.Param", "parameter"), Map.entry("roqme.Timer", "event"),
            Map.entry("roqme.Observation", "event"), Map.entry("roqme.EnumLiteral", "enumMember"),
            Map.entry("roqme.TypeDefinition", "type"), Map.entry("miron.VariationPoint", "variable"),
            Map.entry("miron.BehaviorTreeLiteral", "enumMember"), Map.entry("miron.Rule", "function"),
            Map.entry("miron.Requirement", "function"));

    @Override
    public void provideHighlightingFor(XtextResource resource, IHighlightedPositionAcceptor acceptor,
            CancelIndicator cancelIndicator) {
        if (resource == null || resource.getParseResult() == null) {
            return;
        }
        for (Iterator<EObject> all = resource.getAllContents(); all.hasNext();) {
            if (cancelIndicator != null && cancelIndicator.isCanceled()) {
                return;
            }
            EObject element = all.next();
            String type = typeOf(element.eClass());
            for (EAttribute attribute : element.eClass().getEAllAttributes()) {
                switch (attribute.getName()) {
                case "tag" -> tag(element, attribute, type, acceptor);
                case "name" -> nodes(element, attribute).forEach(node -> names(node, List.of(
                        type == null ? "variable" : type), element.eClass().getName().equals("Attribute") ? null
                                : DECLARATION, acceptor));
                case "alias" -> nodes(element, attribute).forEach(node -> names(node, List.of("namespace"), DECLARATION,
                        acceptor));
                case "function" -> nodes(element, attribute).forEach(node -> names(node, List.of("function"), null,
                        acceptor));
                default -> {
                }
                }
            }
            for (EReference reference : element.eClass().getEAllReferences()) {
                if (reference.isContainment() || reference.isContainer()) {
                    continue;
                }
                List<INode> nodes = NodeModelUtils.findNodesForFeature(element, reference);
                List<?> targets = reference.isMany() ? (List<?>) element.eGet(reference, false)
                        : java.util.Collections.singletonList(element.eGet(reference, false));
                for (int i = 0; i < nodes.size(); i++) {
                    Object target = i < targets.size() ? targets.get(i) : null;
                    if (target instanceof EObject object && !object.eIsProxy()) {
                        String targetType = typeOf(object.eClass());
                        if (targetType != null) {
                            reference(nodes.get(i), targetType, acceptor);
                        }
                    }
                }
            }
        }
    }

    /** The element's tag where it opens and where it closes ({@code <Sequence>} ... {@code </Sequence>}). */
    private static void tag(EObject element, EAttribute attribute, String type, IHighlightedPositionAcceptor acceptor) {
        if (type == null) {
            return;
        }
        Object tag = element.eGet(attribute);
        nodes(element, attribute).forEach(node -> names(node, List.of(type), null, acceptor));
        ICompositeNode whole = NodeModelUtils.getNode(element);
        if (whole == null || tag == null) {
            return;
        }
        boolean closing = false;
        for (ILeafNode leaf : whole.getLeafNodes()) {
            if (leaf.isHidden()) {
                continue;
            }
            if (closing && leaf.getText().equals(tag) && NodeModelUtils.findActualSemanticObjectFor(leaf) == element) {
                acceptor.addPosition(leaf.getOffset(), leaf.getLength(), type);
            }
            closing = leaf.getText().equals("</");
        }
    }

    /**
     * A reference: its last name segment as what it denotes, the segments before as the alias
     * (namespace) or, before "::", the type ({@code roqme::AvailableSpace::HIGH}).
     */
    private static void reference(INode node, String targetType, IHighlightedPositionAcceptor acceptor) {
        List<ILeafNode> segments = new ArrayList<>();
        List<String> separators = new ArrayList<>();
        for (ILeafNode leaf : node.getLeafNodes()) {
            if (leaf.isHidden()) {
                continue;
            }
            if (leaf.getGrammarElement() instanceof Keyword && (leaf.getText().equals(".") || leaf.getText().equals("::"))) {
                separators.add(leaf.getText());
            } else {
                segments.add(leaf);
            }
        }
        for (int i = 0; i < segments.size(); i++) {
            String type;
            if (i == segments.size() - 1) {
                type = targetType;
            } else if (i == segments.size() - 2 && separators.size() > i && separators.get(i).equals("::")) {
                type = "type";
            } else {
                type = "namespace";
            }
            add(segments.get(i), type, null, acceptor);
        }
    }

    /** Each token of a name node, as the given type. */
    private static void names(INode node, List<String> types, String modifier, IHighlightedPositionAcceptor acceptor) {
        for (ILeafNode leaf : node.getLeafNodes()) {
            if (!leaf.isHidden() && !(leaf.getGrammarElement() instanceof Keyword && !Character.isLetter(leaf.getText().charAt(0)))) {
                add(leaf, types.get(0), modifier, acceptor);
            }
        }
    }

    /** A token; a quoted one (BT's "GoTo") without its quotes. */
    private static void add(ILeafNode leaf, String type, String modifier, IHighlightedPositionAcceptor acceptor) {
        String text = leaf.getText();
        int offset = leaf.getOffset();
        int length = leaf.getLength();
        if (length >= 2 && (text.startsWith("\"") && text.endsWith("\"") || text.startsWith("'") && text.endsWith("'"))) {
            offset++;
            length -= 2;
        }
        if (length > 0) {
            if (modifier == null) {
                acceptor.addPosition(offset, length, type);
            } else {
                acceptor.addPosition(offset, length, type, modifier);
            }
        }
    }

    private static List<INode> nodes(EObject element, EAttribute attribute) {
        return NodeModelUtils.findNodesForFeature(element, attribute);
    }

    /** The token type of an element: by metamodel and class, then by its super types. */
    static String typeOf(EClass type) {
        // Nearest first: a SubTreePlus is a SubtreeNode before it is a TreeNode.
        java.util.ArrayDeque<EClass> queue = new java.util.ArrayDeque<>(List.of(type));
        while (!queue.isEmpty()) {
            EClass next = queue.removeFirst();
            String found = TYPES.get(key(next));
            if (found != null) {
                return found;
            }
            queue.addAll(next.getESuperTypes());
        }
        return null;
    }

    private static String key(EClass type) {
        return (type.getEPackage() == null ? "" : type.getEPackage().getName()) + "." + type.getName();
    }
}
