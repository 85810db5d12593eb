package org.miron.bt.ide.nodes;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Set;

import org.miron.bt.nodes.NodeCatalogue;
import org.miron.bt.nodes.NodeModel;
import org.miron.bt.nodes.PortModel;

/**
 * The built-in nodes as completion and hover show them, per BehaviorTree.CPP version: a view of
 * the catalogue (org.miron.bt.nodes), which holds the data.
 */
public final class BuiltinAttributes {
    /** Elements the grammar knows besides nodes. */
    private static final List<String> STRUCTURE = List.of("BehaviorTree", "include", "TreeNodesModel");

    private BuiltinAttributes() {
    }

    /** The element names to propose in a file of this version: its built-ins, then the structure. */
    public static List<String> elements(int version) {
        List<String> all = new ArrayList<>(NodeCatalogue.tags(version));
        all.addAll(STRUCTURE);
        return all;
    }

    /** Whether a grammar keyword is an element name (whatever the version). */
    public static boolean isElement(String keyword) {
        return NodeCatalogue.allTags().contains(keyword) || STRUCTURE.contains(keyword);
    }

    /**
     * The node a tag means in a file of this version; a built-in of the other version too (the
     * validator reports it, completion and hover still describe it).
     */
    public static Optional<NodeModel> node(String tag, int version) {
        return NodeCatalogue.builtin(tag, version).or(() -> NodeCatalogue.find(tag));
    }

    /** The ports of a built-in in a version (those of its own version when it is the other's); empty for a custom node. */
    public static List<PortModel> ports(String tag, int version) {
        return node(tag, version).map(n -> n.ports(n.isIn(version) ? version : otherThan(version))).orElse(List.of());
    }

    /** The fixed values of a built-in's attribute, or an empty list. */
    public static List<String> valuesOf(String tag, String attribute, int version) {
        return ports(tag, version).stream().filter(p -> p.name().equals(attribute)).findFirst()
                .map(PortModel::proposals).orElse(List.of());
    }

    private static int otherThan(int version) {
        Set<Integer> both = NodeCatalogue.BOTH;
        return both.stream().filter(v -> v != version).findFirst().orElse(version);
    }

    /** A built-in as markdown: what it does, its kind, versions and children, and its ports. */
    public static String documentation(NodeModel node, int version) {
        StringBuilder text = new StringBuilder("**").append(node.tag()).append("** (built-in ")
                .append(node.kind().xmlName().toLowerCase()).append(", BehaviorTree.CPP ")
                .append(NodeCatalogue.versionsText(node)).append(")");
        if (node.description() != null) {
            text.append(": ").append(node.description());
        }
        text.append("\n\nChildren: ").append(node.children().describe());
        if (node.counterpart() != null && !node.isIn(version)) {
            text.append(". In version ").append(version).append(" write ").append(node.counterpart().tag());
        }
        List<PortModel> ports = ports(node.tag(), version);
        if (!ports.isEmpty()) {
            text.append("\n");
            for (PortModel port : ports) {
                text.append("\n- `").append(port.name()).append("` (").append(port.direction().xmlName().replace("_port", ""));
                if (port.type().cppName() != null) {
                    text.append(", ").append(port.type().cppName());
                }
                text.append(port.required() ? ", required" : "")
                        .append(port.defaultValue() != null ? ", default " + port.defaultValue() : "").append(')');
                if (port.description() != null) {
                    text.append(": ").append(port.description());
                }
            }
        }
        return text.toString();
    }

    /** The documentation of one port, for an attribute-name proposal. */
    public static String documentation(PortModel port) {
        String type = port.type().cppName() == null ? "" : " " + port.type().cppName();
        return port.direction().xmlName() + type + (port.required() ? ", required" : "")
                + (port.defaultValue() != null ? ", default " + port.defaultValue() : "")
                + (port.description() != null ? ": " + port.description() : "");
    }
}
