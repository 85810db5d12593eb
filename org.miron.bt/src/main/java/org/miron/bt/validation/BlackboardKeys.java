package org.miron.bt.validation;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import org.eclipse.emf.common.util.TreeIterator;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.resource.Resource;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.Precondition;
import org.miron.bt.bt.Script;
import org.miron.bt.bt.ScriptCondition;
import org.miron.bt.bt.SetBlackboard;
import org.miron.bt.bt.SubtreeNode;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.nodes.BuiltinNodes;
import org.miron.bt.nodes.NodeCatalogue;
import org.miron.bt.nodes.NodeDeclaration;
import org.miron.bt.nodes.NodeDeclarations;
import org.miron.bt.nodes.NodeModel;
import org.miron.bt.nodes.PortDirection;
import org.miron.bt.nodes.PortModel;
import org.miron.bt.script.BtScripts;
import org.miron.bt.script.ast.Assignment;
import org.miron.bt.script.ast.Name;
import org.miron.bt.util.BtAttributes;
import org.miron.bt.util.BtFormats;
import org.miron.bt.util.BtTrees;

/**
 * Which blackboard keys the trees of a file and its includes read and write, by name. A port's
 * direction comes from the catalogue for built-ins (SetBlackboard's output_key names the key it
 * writes), from {@code <TreeNodesModel>} for declared nodes, and an undeclared node's port reads
 * (as the executor sends it to the skill). A version-4 script assignment writes. A SubTree call
 * reads or writes the parent key a port remaps to when the called tree reads or writes that port;
 * every port of a call provides the called tree's key of that name (remapped or set to a literal).
 */
final class BlackboardKeys {
    /** A port that reads a key: where it is written, and the key. */
    record Read(Attribute attribute, String key) {
    }

    private record Usage(Set<String> reads, Set<String> writes) {
        static Usage empty() {
            return new Usage(new LinkedHashSet<>(), new LinkedHashSet<>());
        }
    }

    private final Map<String, NodeDeclaration> declarations;
    private final Map<BehaviorTree, Usage> usages = new HashMap<>();
    private final Set<BehaviorTree> visiting = new HashSet<>();
    private final List<Read> reads = new ArrayList<>();
    private final Set<String> written = new LinkedHashSet<>();

    private BlackboardKeys(Resource resource) {
        declarations = NodeDeclarations.visibleFrom(resource);
    }

    /** The keys of the trees visible from a file: its own and its includes'. */
    static BlackboardKeys of(Resource resource) {
        BlackboardKeys keys = new BlackboardKeys(resource);
        for (BehaviorTree tree : BtTrees.visibleTrees(resource).values()) {
            keys.written.addAll(keys.usage(tree).writes());
        }
        for (BehaviorTree tree : BtTrees.treesOf(resource)) {
            keys.written.addAll(keys.usage(tree).writes());
        }
        return keys;
    }

    /** Every key something writes, by name (without the {@code @} of a root key). */
    Set<String> written() {
        return written;
    }

    /** Every port reading a key, in the trees analysed, whatever their file. */
    List<Read> reads() {
        return reads;
    }

    /** The key a port value points at: {@code {key}}, {@code ${key}}, or the port's own name for {@code =} and {@code {=}}. */
    static Optional<String> pointer(String port, String value) {
        if (value == null) {
            return Optional.empty();
        }
        String key = null;
        int n = value.length();
        if (value.equals("=") || value.equals("{=}")) {
            key = port;
        } else if (n >= 3 && value.charAt(0) == '{' && value.charAt(n - 1) == '}') {
            key = value.substring(1, n - 1);
        } else if (n >= 4 && value.startsWith("${") && value.charAt(n - 1) == '}') {
            key = value.substring(2, n - 1);
        }
        return Optional.ofNullable(key).map(k -> k.startsWith("@") ? k.substring(1) : k).filter(k -> !k.isBlank());
    }

    private Usage usage(BehaviorTree tree) {
        Usage known = usages.get(tree);
        if (known != null) {
            return known;
        }
        if (!visiting.add(tree)) {
            return Usage.empty(); // a recursive call: reported elsewhere
        }
        Usage usage = Usage.empty();
        for (TreeIterator<EObject> it = tree.eAllContents(); it.hasNext();) {
            if (it.next() instanceof TreeNode node) {
                node(node, usage);
            }
        }
        visiting.remove(tree);
        usages.put(tree, usage);
        return usage;
    }

    private void node(TreeNode node, Usage usage) {
        int version = BtFormats.versionOf(node);
        scripts(node, version, usage);
        BehaviorTree callee = callee(node);
        if (callee != null) {
            call(node, callee, version, usage);
            return;
        }
        Optional<NodeModel> builtin = BtTrees.isExplicitForm(node) ? Optional.empty()
                : NodeCatalogue.builtin(node.getTag(), version);
        String id = BtTrees.isExplicitForm(node) ? node.attribute(BuiltinNodes.ID) : node.getTag();
        NodeDeclaration declared = builtin.isPresent() || id == null ? null : declarations.get(id);
        for (Attribute attribute : node.getAttributes()) {
            String port = attribute.getName();
            if (skipped(port, version) || builtin.isEmpty() && port.equals(BuiltinNodes.ID)) {
                continue;
            }
            if (node instanceof SetBlackboard && port.equals(BuiltinNodes.OUTPUT_KEY)) {
                // the value names the entry written, braces or not
                String key = pointer(port, attribute.getValue()).orElse(attribute.getValue());
                if (key != null && !key.isBlank()) {
                    usage.writes().add(key);
                }
                continue;
            }
            Optional<String> key = pointer(port, attribute.getValue());
            if (key.isEmpty()) {
                continue;
            }
            PortDirection direction = builtin.flatMap(b -> b.port(port, version)).map(PortModel::direction)
                    .orElseGet(() -> declaredDirection(declared, port));
            if (direction != PortDirection.OUTPUT) {
                read(attribute, key.get(), usage);
            }
            if (direction != PortDirection.INPUT) {
                usage.writes().add(key.get());
            }
        }
    }

    /** A declared node's port direction; an undeclared port reads. */
    private static PortDirection declaredDirection(NodeDeclaration declared, String port) {
        NodeDeclaration.Port declaredPort = declared == null ? null : declared.ports().get(port);
        if (declaredPort == null) {
            return PortDirection.INPUT;
        }
        return declaredPort.reads() && declaredPort.writes() ? PortDirection.INOUT
                : declaredPort.writes() ? PortDirection.OUTPUT : PortDirection.INPUT;
    }

    private void read(Attribute attribute, String key, Usage usage) {
        usage.reads().add(key);
        reads.add(new Read(attribute, key));
    }

    /** The tree a SubTree, SubTreePlus or compact tree tag calls; null for any other node. */
    private static BehaviorTree callee(TreeNode node) {
        if (node instanceof SubtreeNode call) {
            BehaviorTree tree = call.getBehaviorTree();
            return tree == null || tree.eIsProxy() ? null : tree;
        }
        return BtTrees.isCompactSubtree(node) ? BtTrees.visibleTreesOf(node).get(node.getTag()) : null;
    }

    private void call(TreeNode node, BehaviorTree callee, int version, Usage usage) {
        Usage inner = usage(callee);
        NodeDeclaration declared = declarations.get(callee.getName());
        boolean plainSubtree = version == 3 && !(node instanceof org.miron.bt.bt.SubtreePlus);
        boolean shared = plainSubtree && isTrue(node, "__shared_blackboard");
        boolean autoremap = isTrue(node, version == 3 ? "__autoremap" : "_autoremap");
        if (shared || autoremap) {
            inner.writes().stream().filter(k -> shared || version == 3 || !k.startsWith("_")).forEach(usage.writes()::add);
        }
        for (Attribute attribute : node.getAttributes()) {
            String port = attribute.getName();
            if (skipped(port, version) || port.equals(BuiltinNodes.ID) || port.startsWith("__")) {
                continue;
            }
            // the called tree's key of this name is provided, remapped or set to a literal
            written.add(port);
            Optional<String> key = pointer(port, attribute.getValue());
            if (key.isEmpty() && plainSubtree && !shared && attribute.getValue() != null && !attribute.getValue().isBlank()) {
                key = Optional.of(attribute.getValue()); // BT.CPP 3's SubTree remaps by plain name
            }
            if (key.isEmpty()) {
                continue;
            }
            PortDirection direction = declared != null && declared.ports().containsKey(port)
                    ? declaredDirection(declared, port) : null;
            if (direction == PortDirection.INPUT || direction == PortDirection.INOUT
                    || direction == null && inner.reads().contains(port)) {
                read(attribute, key.get(), usage);
            }
            if (direction == PortDirection.OUTPUT || direction == PortDirection.INOUT
                    || direction == null && inner.writes().contains(port)) {
                usage.writes().add(key.get());
            }
        }
    }

    /** Version-4 scripts: an assignment writes its key (reads in scripts are not ports). */
    private void scripts(TreeNode node, int version, Usage usage) {
        if (version != 4) {
            return;
        }
        for (Attribute attribute : node.getAttributes()) {
            String name = attribute.getName();
            boolean script = BtVersions.SCRIPT_DIRECTIVES.contains(name)
                    || (node instanceof Script || node instanceof ScriptCondition) && name.equals(BuiltinNodes.CODE)
                    || node instanceof Precondition && name.equals(BuiltinNodes.IF);
            if (script && attribute.getValue() != null) {
                for (TreeIterator<EObject> it = BtScripts.parse(attribute.getValue()).getScript().eAllContents(); it.hasNext();) {
                    if (it.next() instanceof Assignment assignment && assignment.getTarget() instanceof Name target
                            && target.getName() != null) {
                        String key = target.getName();
                        usage.writes().add(key.startsWith("@") ? key.substring(1) : key);
                    }
                }
            }
        }
    }

    /** Attributes that are no port: the node's name, version-4 scripts and settings. */
    private static boolean skipped(String attribute, int version) {
        return attribute.equals("name") || version == 4 && attribute.startsWith("_");
    }

    private static boolean isTrue(TreeNode node, String attribute) {
        String value = BtAttributes.value(node.getAttributes(), attribute);
        return value != null && (value.trim().equalsIgnoreCase("true") || value.trim().equals("1"));
    }
}
