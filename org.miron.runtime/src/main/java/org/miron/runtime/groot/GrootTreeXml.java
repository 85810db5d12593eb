package org.miron.runtime.groot;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.miron.bt.nodes.NodeCatalogue;
import org.miron.bt.nodes.NodeKind;
import org.miron.bt.nodes.NodeModel;
import org.miron.bt.nodes.PortDirection;
import org.miron.bt.nodes.PortModel;
import org.miron.executor.Node;
import org.miron.executor.decorators.SubTreeNode;

/**
 * The FULLTREE reply: the instantiated tree as BT.CPP's WriteTreeToXML writes it with metadata, one
 * {@code <BehaviorTree ID _fullpath>} per subtree instance, each node as the element of its
 * registration name with {@code name} (a SubTree: {@code ID} and {@code _fullpath}), {@code _uid},
 * its ports (a built-in's defaults added, as the library adds them when it builds the node) and its
 * pre/post-conditions; then a {@code <TreeNodesModel>} of the node types the tree uses. Printed as
 * tinyxml2 prints: four spaces a level, empty elements closed with {@code />}.
 */
public final class GrootTreeXml {
    /** BT.CPP's PreCond then PostCond names, in the order of its enums (its maps are ordered by them). */
    private static final List<String> CONDITIONS = List.of("_failureIf", "_successIf", "_skipIf", "_while",
            "_onHalted", "_onFailure", "_onSuccess", "_post");

    private final GrootTree tree;
    private final DeclaredModels declared;
    private final StringBuilder out = new StringBuilder();
    /** Registration name → the model written in TreeNodesModel, sorted as the library's std::map. */
    private final Map<String, Node> models = new TreeMap<>();

    private GrootTreeXml(GrootTree tree, DeclaredModels declared) {
        this.tree = tree;
        this.declared = declared;
    }

    static String write(GrootTree tree, DeclaredModels declared) {
        return new GrootTreeXml(tree, declared).document();
    }

    /**
     * The tree as FULLTREE sends it and FileLogger2 writes it in a recording's header, the
     * application's node models as {@code treeFile} declares them (null: none).
     */
    public static String write(GrootTree tree, java.nio.file.Path treeFile) {
        return write(tree, treeFile == null ? DeclaredModels.none() : DeclaredModels.of(treeFile));
    }

    private String document() {
        out.append("<root BTCPP_format=\"4\">\n");
        for (GrootTree.Subtree subtree : tree.subtrees()) {
            out.append("    <BehaviorTree ID=\"").append(escape(subtree.treeId())).append("\" _fullpath=\"")
                    .append(escape(subtree.instanceName())).append("\">\n");
            node(subtree.nodes().get(0), 2);
            out.append("    </BehaviorTree>\n");
        }
        if (models.isEmpty()) {
            out.append("    <TreeNodesModel/>\n");
        } else {
            out.append("    <TreeNodesModel>\n");
            models.forEach((id, node) -> model(id, node));
            out.append("    </TreeNodesModel>\n");
        }
        out.append("</root>\n");
        return out.toString();
    }

    private void node(Node node, int depth) {
        Map<String, String> attributes = new LinkedHashMap<>();
        if (node instanceof SubTreeNode call) {
            attributes.put("ID", call.treeId());
            attributes.put("_fullpath", tree.fullPath(node));
        } else {
            attributes.put("name", node.name());
            models.putIfAbsent(node.element(), node);
        }
        attributes.put("_uid", Integer.toString(tree.uid(node)));
        attributes.putAll(ports(node));
        for (String condition : CONDITIONS) {
            String script = node.ports().raw(condition);
            if (script != null) {
                attributes.put(condition, script);
            }
        }
        List<Node> children = node instanceof SubTreeNode ? List.of() : node.children();
        open(node.element(), attributes, depth, children.isEmpty());
        for (Node child : children) {
            node(child, depth + 1);
        }
        if (!children.isEmpty()) {
            out.append("    ".repeat(depth)).append("</").append(node.element()).append(">\n");
        }
    }

    /** The node's ports: its attributes that are port names (a letter first, not name or ID), then a built-in's defaults. */
    private static Map<String, String> ports(Node node) {
        Map<String, String> ports = new LinkedHashMap<>();
        node.ports().attributes().forEach((name, value) -> {
            if (isPortName(name)) {
                ports.put(name, value);
            }
        });
        if (!(node instanceof SubTreeNode)) {
            builtin(node).ifPresent(model -> {
                for (PortModel port : model.ports(4)) {
                    if (port.defaultValue() != null && !port.defaultValue().isEmpty() && port.direction() != PortDirection.OUTPUT) {
                        ports.putIfAbsent(port.name(), port.defaultValue());
                    }
                }
            });
        }
        return ports;
    }

    private static java.util.Optional<NodeModel> builtin(Node node) {
        return NodeCatalogue.find(node.element()).filter(m -> m.isIn(4) && !m.explicitForm());
    }

    static boolean isPortName(String name) {
        return !name.isEmpty() && Character.isLetter(name.charAt(0)) && !name.equals("name") && !name.equals("ID");
    }

    /** A built-in's model from the catalogue; the application's as its file declares it, else its ports as inputs. */
    private void model(String id, Node node) {
        Map<String, String> attributes = Map.of("ID", id);
        Map<String, String> ports = new TreeMap<>();
        DeclaredModels.Model model = declared.get(id);
        String kind = model != null ? model.kind() : elementOf(node.kind());
        if (builtin(node).isPresent()) {
            builtin(node).get().ports(4).forEach(p -> ports.put(p.name(), direction(p.direction())));
        } else if (model != null) {
            ports.putAll(model.ports());
        } else {
            node.ports().attributes().keySet().stream().filter(GrootTreeXml::isPortName).forEach(p -> ports.put(p, "input_port"));
        }
        open(kind, attributes, 2, ports.isEmpty());
        ports.forEach((name, element) -> open(element, Map.of("name", name), 3, true));
        if (!ports.isEmpty()) {
            out.append("        </").append(kind).append(">\n");
        }
    }

    private static String elementOf(NodeKind kind) {
        switch (kind) {
        case CONTROL:
            return "Control";
        case DECORATOR:
            return "Decorator";
        case CONDITION:
            return "Condition";
        case SUBTREE:
            return "SubTree";
        default:
            return "Action";
        }
    }

    private static String direction(PortDirection direction) {
        switch (direction) {
        case OUTPUT:
            return "output_port";
        case INOUT:
            return "inout_port";
        default:
            return "input_port";
        }
    }

    private void open(String element, Map<String, String> attributes, int depth, boolean empty) {
        out.append("    ".repeat(depth)).append('<').append(element);
        attributes.forEach((name, value) -> out.append(' ').append(name).append("=\"").append(escape(value)).append('"'));
        out.append(empty ? "/>\n" : ">\n");
    }

    /** tinyxml2 escapes these five in attribute values. */
    static String escape(String text) {
        StringBuilder escaped = new StringBuilder(text.length());
        for (char c : text.toCharArray()) {
            switch (c) {
            case '"' -> escaped.append("&quot;");
            case '&' -> escaped.append("&amp;");
            case '\'' -> escaped.append("&apos;");
            case '<' -> escaped.append("&lt;");
            case '>' -> escaped.append("&gt;");
            default -> escaped.append(c);
            }
        }
        return escaped.toString();
    }
}
