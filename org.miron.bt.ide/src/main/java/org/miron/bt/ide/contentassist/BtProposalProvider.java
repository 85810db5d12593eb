package org.miron.bt.ide.contentassist;

import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.xtext.CrossReference;
import org.eclipse.xtext.Keyword;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistContext;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistEntry;
import org.eclipse.xtext.ide.editor.contentassist.IIdeContentProposalAcceptor;
import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalProvider;
import org.eclipse.xtext.resource.XtextResource;
import org.miron.bt.ide.nodes.BuiltinAttributes;
import org.miron.bt.ide.nodes.NodeDeclaration;
import org.miron.bt.ide.nodes.NodeDeclarations;
import org.miron.bt.util.BtTrees;

/**
 * BT completion: the grammar's keywords (built-in element names) plus, read from the text around
 * the caret, node IDs declared in {@code <TreeNodesModel>} (here and in included files), SubTree
 * and main tree IDs, the attribute names of known nodes (declared ports, built-ins' parameters)
 * and the values of attributes with a fixed set of them.
 */
public class BtProposalProvider extends IdeContentProposalProvider {
    private static final Set<String> EXPLICIT_FORMS = Set.of("Action", "Condition", "Control", "Decorator");
    private static final Set<String> SUBTREE_FORMS = Set.of("SubTree", "SubTreePlus");

    @Override
    public void createProposals(Collection<ContentAssistContext> contexts, IIdeContentProposalAcceptor acceptor) {
        super.createProposals(contexts, acceptor);
        ContentAssistContext first = contexts.stream().findFirst().orElse(null);
        if (first == null || first.getResource() == null) {
            return;
        }
        XtextResource resource = first.getResource();
        String text = first.getRootNode() != null ? first.getRootNode().getText() : "";
        TagContext tag = TagContext.at(text, first.getOffset());
        List<ContentAssistEntry> entries = switch (tag.kind()) {
            case ELEMENT_NAME -> elementNames(resource);
            case ATTRIBUTE_NAME -> attributeNames(resource, tag);
            case ATTRIBUTE_VALUE -> attributeValues(resource, tag);
            case NONE -> List.of();
        };
        for (ContentAssistEntry entry : entries) {
            if (entry.getProposal().startsWith(tag.partial()) && acceptor.canAcceptMoreProposals()) {
                entry.setPrefix(tag.partial());
                acceptor.accept(entry, 600);
            }
        }
    }

    // SubTree IDs come from the text (without the quotes the cross-reference proposals would add).
    @Override
    protected void _createProposals(CrossReference reference, ContentAssistContext context,
            IIdeContentProposalAcceptor acceptor) {
    }

    // Element names after '<' come from the text (the parser proposes them only in some states).
    @Override
    protected boolean filterKeyword(Keyword keyword, ContentAssistContext context) {
        return !BuiltinAttributes.ELEMENTS.contains(keyword.getValue()) || context.getRootNode() == null
                || TagContext.at(context.getRootNode().getText(), context.getOffset()).kind() != TagContext.Kind.ELEMENT_NAME;
    }

    /** Built-ins, and compact forms: <MoveTo x="1"/> for a declared node, <GoTo/> for a tree. */
    private static List<ContentAssistEntry> elementNames(XtextResource resource) {
        Map<String, ContentAssistEntry> result = new LinkedHashMap<>();
        for (String builtin : BuiltinAttributes.ELEMENTS) {
            result.put(builtin, entry(builtin, "built-in", ContentAssistEntry.KIND_KEYWORD, null));
        }
        for (NodeDeclaration node : NodeDeclarations.visibleFrom(resource).values()) {
            result.putIfAbsent(node.id(), entry(node.id(), node.kind(), ContentAssistEntry.KIND_CLASS, portsText(node)));
        }
        for (String tree : BtTrees.visibleTrees(resource).keySet()) {
            // A tree also declared as a SubTree in TreeNodesModel keeps the declaration, with its ports.
            result.putIfAbsent(tree, entry(tree, "BehaviorTree", ContentAssistEntry.KIND_MODULE, null));
        }
        return new ArrayList<>(result.values());
    }

    private static List<ContentAssistEntry> attributeValues(XtextResource resource, TagContext tag) {
        if ("ID".equals(tag.attribute())) {
            return idValues(resource, tag);
        }
        List<ContentAssistEntry> result = new ArrayList<>();
        if ("root".equals(tag.tag()) && "main_tree_to_execute".equals(tag.attribute())) {
            for (String tree : BtTrees.visibleTrees(resource).keySet()) {
                result.add(entry(tree, "BehaviorTree", ContentAssistEntry.KIND_REFERENCE, null));
            }
        }
        for (String value : BuiltinAttributes.valuesOf(tag.attribute())) {
            result.add(entry(value, tag.attribute(), ContentAssistEntry.KIND_VALUE, null));
        }
        return result;
    }

    private static List<ContentAssistEntry> idValues(XtextResource resource, TagContext tag) {
        List<ContentAssistEntry> result = new ArrayList<>();
        if (SUBTREE_FORMS.contains(tag.tag())) {
            for (String tree : BtTrees.visibleTrees(resource).keySet()) {
                result.add(entry(tree, "BehaviorTree", ContentAssistEntry.KIND_REFERENCE, null));
            }
        } else if (EXPLICIT_FORMS.contains(tag.tag())) {
            for (NodeDeclaration node : NodeDeclarations.visibleFrom(resource).values()) {
                if (node.kind().equals(tag.tag())) {
                    result.add(entry(node.id(), node.kind(), ContentAssistEntry.KIND_REFERENCE, portsText(node)));
                }
            }
        }
        return result;
    }

    private static List<ContentAssistEntry> attributeNames(XtextResource resource, TagContext tag) {
        Map<String, ContentAssistEntry> names = new LinkedHashMap<>();
        String id = EXPLICIT_FORMS.contains(tag.tag()) || SUBTREE_FORMS.contains(tag.tag()) ? tag.attributes().get("ID")
                : tag.tag();
        NodeDeclaration declared = id == null ? null : NodeDeclarations.visibleFrom(resource).get(id);
        if (declared != null) {
            for (NodeDeclaration.Port port : declared.ports().values()) {
                names.put(port.name(), entry(port.name(), port.direction(), ContentAssistEntry.KIND_PROPERTY,
                        port.description()));
            }
        }
        List<String> builtin = BuiltinAttributes.of(tag.tag());
        if (builtin != null) {
            builtin.forEach(a -> names.putIfAbsent(a, entry(a, tag.tag() + " attribute", ContentAssistEntry.KIND_PROPERTY, null)));
        }
        if (declared != null || builtin != null || tag.tag() != null) {
            names.putIfAbsent("name", entry("name", "node name", ContentAssistEntry.KIND_PROPERTY, null));
        }
        tag.attributes().keySet().forEach(names::remove);
        return new ArrayList<>(names.values());
    }

    private static String portsText(NodeDeclaration node) {
        if (node.ports().isEmpty()) {
            return null;
        }
        StringBuilder text = new StringBuilder();
        for (NodeDeclaration.Port port : node.ports().values()) {
            text.append(port.direction()).append(' ').append(port.name());
            if (port.description() != null && !port.description().isEmpty()) {
                text.append(": ").append(port.description());
            }
            text.append('\n');
        }
        return text.toString().trim();
    }

    private static ContentAssistEntry entry(String proposal, String description, String kind, String documentation) {
        ContentAssistEntry entry = new ContentAssistEntry();
        entry.setProposal(proposal);
        entry.setDescription(description);
        entry.setKind(kind);
        entry.setDocumentation(documentation);
        return entry;
    }
}
