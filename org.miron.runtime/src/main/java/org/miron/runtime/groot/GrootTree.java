package org.miron.runtime.groot;

import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import org.miron.executor.Blackboard;
import org.miron.executor.Node;
import org.miron.executor.Tree;
import org.miron.executor.decorators.SubTreeNode;

/**
 * Our tree as BehaviorTree.CPP 4 instantiates it, which is what Groot2 is told: every node numbered
 * from 1 depth first with each SubTree expanded in place (the library numbers nodes as it creates
 * them), and the list of subtree instances in the order they were created, each with its nodes
 * (those of nested SubTrees excluded), its blackboard and its instance name
 * ({@code parent/name}, or {@code parent/ID::uid} when the SubTree has no name; the main tree's is
 * empty).
 */
public final class GrootTree {
    /** One instance of a tree: the main tree or one SubTree call's. */
    public record Subtree(String treeId, String instanceName, Blackboard blackboard, List<Node> nodes) {
        /** Its name in BLACKBOARD requests: the instance name, the tree ID for the main tree. */
        public String name() {
            return instanceName.isEmpty() ? treeId : instanceName;
        }
    }

    private final List<Node> byUid = new ArrayList<>();
    private final Map<Node, Integer> uids = new IdentityHashMap<>();
    private final Map<Node, String> fullPaths = new IdentityHashMap<>();
    private final List<Subtree> subtrees = new ArrayList<>();

    public GrootTree(Tree tree) {
        instantiate(tree.id(), "", "", tree.root(), tree.blackboard());
    }

    private void instantiate(String treeId, String instanceName, String prefix, Node root, Blackboard blackboard) {
        Subtree subtree = new Subtree(treeId, instanceName, blackboard, new ArrayList<>());
        subtrees.add(subtree);
        number(root, subtree, prefix);
    }

    private void number(Node node, Subtree subtree, String prefix) {
        int uid = byUid.size() + 1;
        byUid.add(node);
        uids.put(node, uid);
        subtree.nodes().add(node);
        String nameAttribute = node.ports().raw("name");
        if (node instanceof SubTreeNode call) {
            String instance = nameAttribute != null ? nameAttribute : call.treeId();
            // the library appends ::uid to a path whose name is only the type ID
            fullPaths.put(node, prefix + instance + (instance.equals(call.treeId()) ? "::" + uid : ""));
            String path = (subtree.instanceName().isEmpty() ? "" : subtree.instanceName() + "/")
                    + (nameAttribute != null ? nameAttribute : call.treeId() + "::" + uid);
            for (Node child : node.children()) {
                instantiate(call.treeId(), path, path + "/", child, call.blackboard());
            }
            return;
        }
        for (Node child : node.children()) {
            number(child, subtree, prefix);
        }
    }

    /** The node with this uid, or null. */
    public Node node(int uid) {
        return uid >= 1 && uid <= byUid.size() ? byUid.get(uid - 1) : null;
    }

    /** The node's uid, or 0 for a node not in the tree. */
    public int uid(Node node) {
        Integer uid = uids.get(node);
        return uid == null ? 0 : uid;
    }

    public int size() {
        return byUid.size();
    }

    /** A SubTree node's path as the library writes it in {@code _fullpath}. */
    public String fullPath(Node subtreeCall) {
        return fullPaths.get(subtreeCall);
    }

    public List<Subtree> subtrees() {
        return Collections.unmodifiableList(subtrees);
    }
}
