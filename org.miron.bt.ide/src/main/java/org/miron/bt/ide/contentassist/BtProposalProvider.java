package org.miron.bt.ide.contentassist;

import java.util.ArrayList;
import java.util.Collection;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;

import org.eclipse.xtext.CrossReference;
import org.eclipse.xtext.Keyword;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistContext;
import org.eclipse.xtext.ide.editor.contentassist.ContentAssistEntry;
import org.eclipse.xtext.ide.editor.contentassist.IIdeContentProposalAcceptor;
import org.eclipse.xtext.ide.editor.contentassist.IdeContentProposalProvider;
import org.eclipse.xtext.resource.XtextResource;
import org.miron.bt.bt.BTModel;
import org.miron.bt.ide.nodes.BuiltinAttributes;
import org.miron.bt.nodes.NodeDeclaration;
import org.miron.bt.nodes.NodeDeclarations;
import org.miron.bt.nodes.NodeCatalogue;
import org.miron.bt.nodes.NodeKind;
import org.miron.bt.nodes.NodeModel;
import org.miron.bt.nodes.PortModel;
import org.miron.bt.util.BtFormats;
import org.miron.bt.util.BtTrees;

/**
 * BT completion: the built-in element names of the file's BehaviorTree.CPP version (from the
 * catalogue, org.miron.bt.nodes) plus, read from the text around
 * the caret, node IDs declared in {@code <TreeNodesModel>} (here and in included files), SubTree
 * and main tree IDs, the attribute names of known nodes (declared ports, built-ins' parameters)
 * and the values of attributes with a fixed set of them.
 */
public class BtProposalProvider extends IdeContentProposalProvider {
    /** Action, Condition, Control, Decorator: their ID names a registered node. */
    private static final Set<String> EXPLICIT_FORMS = NodeCatalogue.all().stream()
            .filter(n -> n.explicitForm() && n.kind() != NodeKind.SUBTREE).map(NodeModel::tag)
            .collect(Collectors.toUnmodifiableSet());
    /** SubTree, SubTreePlus: their ID names a tree. */
    private static final Set<String> SUBTREE_FORMS = NodeCatalogue.all().stream()
            .filter(n -> n.kind() == NodeKind.SUBTREE).map(NodeModel::tag).collect(Collectors.toUnmodifiableSet());
    private static final Pattern FORMAT = Pattern.compile("<root\\b[^>]*\\b" + BtFormats.ATTRIBUTE + "\\s*=\\s*[\"'](\\d+)");

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
        int version = versionOf(resource, text);
        List<ContentAssistEntry> entries = switch (tag.kind()) {
            case ELEMENT_NAME -> elementNames(resource, version);
            case ATTRIBUTE_NAME -> attributeNames(resource, tag, version);
            case ATTRIBUTE_VALUE -> attributeValues(resource, tag, version);
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

    /**
     * Inside a tag the text decides (issue 23, items 6 and 7): after '<' only the names the file's
     * version has, and root (not '<', '</', nor the other version's built-ins the grammar also knows); among
     * attributes only '>' and '/>' from the grammar (the names come from the text, without those
     * written already and those of the other version); in a value nothing.
     */
    @Override
    protected boolean filterKeyword(Keyword keyword, ContentAssistContext context) {
        if (context.getRootNode() == null) {
            return true;
        }
        TagContext tag = TagContext.at(context.getRootNode().getText(), context.getOffset());
        String value = keyword.getValue();
        return switch (tag.kind()) {
            case ELEMENT_NAME -> value.equals("root");
            case ATTRIBUTE_NAME -> value.equals(">") || value.equals("/>");
            case ATTRIBUTE_VALUE -> false;
            case NONE -> true;
        };
    }

    /**
     * The file's BehaviorTree.CPP version: from the model's root, else (a root start tag the parser
     * has not made an element of yet) from the text; 3 without BTCPP_format.
     */
    static int versionOf(XtextResource resource, String text) {
        int version;
        if (!resource.getContents().isEmpty() && resource.getContents().get(0) instanceof BTModel model) {
            version = model.formatVersion();
        } else {
            Matcher format = FORMAT.matcher(text);
            version = format.find() ? Integer.parseInt(format.group(1)) : BtFormats.DEFAULT_VERSION;
        }
        // BTCPP_format="5" is an error of its own: propose as for the default meanwhile.
        return NodeCatalogue.BOTH.contains(version) ? version : BtFormats.DEFAULT_VERSION;
    }

    /**
     * The built-ins of the file's version, and compact forms: <MoveTo x="1"/> for a declared node,
     * <GoTo/> for a tree.
     */
    private static List<ContentAssistEntry> elementNames(XtextResource resource, int version) {
        Map<String, ContentAssistEntry> result = new LinkedHashMap<>();
        for (String builtin : BuiltinAttributes.elements(version)) {
            String documentation = NodeCatalogue.find(builtin).map(n -> BuiltinAttributes.documentation(n, version))
                    .orElse(null);
            result.put(builtin, entry(builtin, "built-in", ContentAssistEntry.KIND_KEYWORD, documentation));
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

    private static List<ContentAssistEntry> attributeValues(XtextResource resource, TagContext tag, int version) {
        if ("ID".equals(tag.attribute())) {
            return idValues(resource, tag);
        }
        List<ContentAssistEntry> result = new ArrayList<>();
        if ("root".equals(tag.tag()) && "main_tree_to_execute".equals(tag.attribute())) {
            for (String tree : BtTrees.visibleTrees(resource).keySet()) {
                result.add(entry(tree, "BehaviorTree", ContentAssistEntry.KIND_REFERENCE, null));
            }
        }
        for (String value : BuiltinAttributes.valuesOf(tag.tag(), tag.attribute(), version)) {
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

    private static List<ContentAssistEntry> attributeNames(XtextResource resource, TagContext tag, int version) {
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
        for (PortModel port : BuiltinAttributes.ports(tag.tag(), version)) {
            names.putIfAbsent(port.name(), entry(port.name(), tag.tag() + " attribute", ContentAssistEntry.KIND_PROPERTY,
                    BuiltinAttributes.documentation(port)));
        }
        if (EXPLICIT_FORMS.contains(tag.tag()) || SUBTREE_FORMS.contains(tag.tag()) || "BehaviorTree".equals(tag.tag())) {
            names.putIfAbsent("ID", entry("ID", tag.tag() + " attribute", ContentAssistEntry.KIND_PROPERTY, null));
        }
        if (tag.tag() != null && !"BehaviorTree".equals(tag.tag()) && !"root".equals(tag.tag())
                && !"include".equals(tag.tag())) {
            names.putIfAbsent("name", entry("name", "node name", ContentAssistEntry.KIND_PROPERTY, null));
        }
        if ("root".equals(tag.tag())) {
            names.putIfAbsent("main_tree_to_execute", entry("main_tree_to_execute", "root attribute",
                    ContentAssistEntry.KIND_PROPERTY, null));
            names.putIfAbsent("BTCPP_format", entry("BTCPP_format", "root attribute", ContentAssistEntry.KIND_PROPERTY,
                    null));
        }
        if ("include".equals(tag.tag())) {
            names.putIfAbsent("path", entry("path", "include attribute", ContentAssistEntry.KIND_PROPERTY, null));
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
