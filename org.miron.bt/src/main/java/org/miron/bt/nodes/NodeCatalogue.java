package org.miron.bt.nodes;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import org.miron.bt.conversion.XmlStrings;

/**
 * Lookups in the table of built-in nodes ({@link BuiltinNodes}): by element name, by element name
 * in one BehaviorTree.CPP version, all of a version. Built once, immutable, safe to share.
 */
public final class NodeCatalogue {
    public static final int V3 = 3;
    public static final int V4 = 4;
    /** Declared before the table, which uses it while this class initialises. */
    public static final Set<Integer> BOTH = Set.of(V3, V4);

    private static final List<NodeModel> ALL = List.copyOf(BuiltinNodes.table());
    private static final Map<String, NodeModel> BY_TAG = index();

    private NodeCatalogue() {
    }

    private static Map<String, NodeModel> index() {
        Map<String, NodeModel> index = new LinkedHashMap<>();
        for (NodeModel node : ALL) {
            for (String tag : node.tags()) {
                if (index.put(tag, node) != null) {
                    throw new IllegalStateException("built-in tag " + tag + " is in the catalogue twice");
                }
            }
        }
        return Map.copyOf(index);
    }

    /** Every entry, in the order of the grammar's ElementKeyword. */
    public static List<NodeModel> all() {
        return ALL;
    }

    /** The entry of an element name (a tag or another spelling), whatever the version. */
    public static Optional<NodeModel> find(String tag) {
        return Optional.ofNullable(tag == null ? null : BY_TAG.get(tag));
    }

    /** The entry, when {@code tag} names a built-in in {@code version}; empty for a custom or other-version node. */
    public static Optional<NodeModel> builtin(String tag, int version) {
        return find(tag).filter(node -> node.accepts(tag, version));
    }

    /** The entry of a tag that must exist (code that writes trees): an unknown tag is a programming error. */
    public static NodeModel require(String tag) {
        return find(tag).orElseThrow(() -> new IllegalArgumentException("no built-in node " + tag));
    }

    /** The entries of one version. */
    public static List<NodeModel> in(int version) {
        return ALL.stream().filter(node -> node.isIn(version)).toList();
    }

    /** The element names to propose in a file of {@code version}: each node's tag, not its old spellings. */
    public static List<String> tags(int version) {
        return in(version).stream().map(NodeModel::tag).toList();
    }

    /** Every element name the catalogue knows: tags and spellings, of both versions. */
    public static Set<String> allTags() {
        return BY_TAG.keySet();
    }

    /**
     * The element names built in {@code version} but not in the other, each with what the other
     * version writes instead ("" when it has no equivalent).
     */
    public static Map<String, String> onlyIn(int version) {
        int other = version == V3 ? V4 : V3;
        Map<String, String> result = new LinkedHashMap<>();
        for (NodeModel node : ALL) {
            for (String tag : node.tags()) {
                if (node.accepts(tag, version) && !node.accepts(tag, other)) {
                    String instead = node.isIn(other) ? node.tag()
                            : node.counterpart() != null ? node.counterpart().tag() : "";
                    result.put(tag, instead);
                }
            }
        }
        return Map.copyOf(result);
    }

    /**
     * Whether writing {@code instead} for the element {@code tag} keeps the node's meaning (a
     * quick fix may rename it): another spelling, or a counterpart marked as a rename.
     */
    public static boolean isRename(String tag, String instead) {
        NodeModel node = find(tag).orElse(null);
        if (node == null) {
            return false;
        }
        return node.tags().contains(instead)
                || node.counterpart() != null && node.counterpart().tag().equals(instead) && node.counterpart().rename();
    }

    /**
     * The built-ins of a version as BehaviorTree.CPP's writeTreeNodesModelXML writes a manifest
     * (the explicit forms, which name other nodes, left out): what Groot reads.
     */
    public static String treeNodesModel(int version) {
        StringBuilder xml = new StringBuilder("<TreeNodesModel>\n");
        for (NodeModel node : in(version)) {
            if (node.explicitForm() && node.kind() != NodeKind.SUBTREE) {
                continue;
            }
            List<PortModel> ports = new ArrayList<>(node.ports(version));
            ports.removeIf(p -> p.name().equals(BuiltinNodes.ID));
            xml.append("  <").append(node.kind().xmlName()).append(" ID=\"").append(node.tag()).append('"');
            if (ports.isEmpty()) {
                xml.append("/>\n");
                continue;
            }
            xml.append(">\n");
            for (PortModel port : ports) {
                xml.append("    <").append(port.direction().xmlName()).append(" name=\"").append(port.name()).append('"');
                if (port.type().cppName() != null) {
                    xml.append(" type=").append(XmlStrings.quote(port.type().cppName()));
                }
                if (port.defaultValue() != null) {
                    xml.append(" default=").append(XmlStrings.quote(port.defaultValue()));
                }
                String doc = port.description() == null ? "" : text(port.description());
                xml.append(doc.isEmpty() ? "/>\n" : ">" + doc + "</" + port.direction().xmlName() + ">\n");
            }
            xml.append("  </").append(node.kind().xmlName()).append(">\n");
        }
        return xml.append("</TreeNodesModel>\n").toString();
    }

    private static String text(String value) {
        String quoted = XmlStrings.quote(value);
        return quoted.substring(1, quoted.length() - 1);
    }

    /** The versions of a node as text: "3 and 4", "3", "4". */
    public static String versionsText(NodeModel node) {
        return node.isIn(V3) && node.isIn(V4) ? "3 and 4" : node.isIn(V3) ? "3" : "4";
    }
}
