package org.miron.bt.ide.hover;

import java.util.ArrayList;
import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.TerminalRule;
import org.eclipse.xtext.documentation.IEObjectDocumentationProvider;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.ILeafNode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.ide.nodes.BuiltinAttributes;
import org.miron.bt.nodes.NodeDeclaration;
import org.miron.bt.nodes.NodeDeclarations;
import org.miron.bt.util.BtFormats;

/**
 * Hover text of BT elements (markdown): the XML comment just before the element, for a built-in
 * what the catalogue says of it in the file's version (org.miron.bt.nodes), and for a tree or a
 * declared node its ports from {@code <TreeNodesModel>}.
 */
public class BtDocumentationProvider implements IEObjectDocumentationProvider {

    @Override
    public String getDocumentation(EObject element) {
        return documentation(element);
    }

    /** Static so the MIRoN language's hover can describe the trees it imports the same way. */
    public static String documentation(EObject element) {
        // Over an attribute (<Action ID="MoveTo" x="1"/>) the node is what the reader wants described.
        if (element instanceof Attribute && element.eContainer() instanceof TreeNode node) {
            element = node;
        }
        List<String> parts = new ArrayList<>();
        String header = header(element);
        if (header != null) {
            parts.add(header);
        }
        String comment = leadingComment(element);
        if (comment != null) {
            parts.add(comment);
        }
        if (element instanceof TreeNode node && node.getTag() != null) {
            int version = BtFormats.versionOf(node);
            BuiltinAttributes.node(node.getTag(), version)
                    .ifPresent(builtin -> parts.add(BuiltinAttributes.documentation(builtin, version)));
        }
        String id = idOf(element);
        if (id != null && element.eResource() != null) {
            NodeDeclaration declaration = NodeDeclarations.visibleFrom(element.eResource()).get(id);
            if (declaration != null) {
                parts.add(ports(declaration));
            }
        }
        return parts.isEmpty() ? null : String.join("\n\n", parts);
    }

    /**
     * What a tree or node is and where it is defined (issue 23, item 5: a tree without comment or
     * declared ports had no hover at all, also from the .miron that names it):
     * "**BehaviorTree** `Charge` — `intralogistics.bt` line 15".
     */
    private static String header(EObject element) {
        StringBuilder text = new StringBuilder();
        if (element instanceof BehaviorTree tree) {
            text.append("**BehaviorTree**");
            if (tree.getName() != null) {
                text.append(" `").append(tree.getName()).append('`');
            }
        } else if (element instanceof TreeNode node && node.getTag() != null) {
            text.append("**").append(node.getTag()).append("**");
            String id = node.attribute("ID");
            if (id != null) {
                text.append(" `").append(id).append('`');
            }
            String name = node.attribute("name");
            if (name != null) {
                text.append(" named `").append(name).append('`');
            }
            BehaviorTree tree = org.eclipse.xtext.EcoreUtil2.getContainerOfType(node, BehaviorTree.class);
            if (tree != null && tree.getName() != null) {
                text.append(" in BehaviorTree `").append(tree.getName()).append('`');
            }
        } else {
            return null;
        }
        ICompositeNode node = NodeModelUtils.findActualNodeFor(element);
        if (node != null && element.eResource() != null && element.eResource().getURI() != null) {
            String all = node.getRootNode().getText();
            int line = 1;
            for (int i = 0; i < node.getOffset() && i < all.length(); i++) {
                if (all.charAt(i) == '\n') {
                    line++;
                }
            }
            text.append(" — `").append(element.eResource().getURI().lastSegment()).append("` line ").append(line);
        }
        return text.toString();
    }

    private static String idOf(EObject element) {
        if (element instanceof BehaviorTree tree) {
            return tree.getName();
        }
        if (element instanceof TreeNode node) {
            String id = node.attribute("ID");
            return id != null ? id : node.getTag();
        }
        return null;
    }

    /** `<Action ID="MoveTo">` ports as a markdown list. */
    public static String ports(NodeDeclaration declaration) {
        StringBuilder text = new StringBuilder("**" + declaration.kind() + " " + declaration.id() + "**");
        if (declaration.ports().isEmpty()) {
            return text.append(": no ports").toString();
        }
        text.append(", ports:\n");
        for (NodeDeclaration.Port port : declaration.ports().values()) {
            text.append("\n- `").append(port.name()).append("` (").append(port.direction().replace("_port", ""))
                    .append(')');
            if (port.description() != null && !port.description().isEmpty()) {
                text.append(": ").append(port.description());
            }
        }
        return text.toString();
    }

    /** The XML comment right before the element (the hidden tokens its node starts with). */
    private static String leadingComment(EObject element) {
        ICompositeNode node = NodeModelUtils.getNode(element);
        if (node == null) {
            return null;
        }
        String comment = null;
        for (ILeafNode leaf : node.getLeafNodes()) {
            if (!leaf.isHidden()) {
                break;
            }
            if (leaf.getGrammarElement() instanceof TerminalRule rule && "XML_COMMENT".equals(rule.getName())) {
                comment = leaf.getText();
            }
        }
        if (comment == null) {
            return null;
        }
        return comment.substring(4, comment.length() - 3).strip().replaceAll("\\s*\\R\\s*", "\n");
    }
}
