package org.miron.generator;

import static org.miron.bt.nodes.BuiltinNodes.AUTOREMAP;
import static org.miron.bt.nodes.BuiltinNodes.SHARED_BLACKBOARD;
import static org.miron.bt.nodes.BuiltinNodes.V3_AUTOREMAP;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;

import org.eclipse.xtext.EcoreUtil2;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.SubtreeNode;
import org.miron.bt.bt.SubtreePlus;
import org.miron.bt.nodes.PortType;

/**
 * Makes the keys the runtime writes into the main tree's blackboard ({vp_sel}, {vp}) visible to
 * the subtrees that read them. A subtree called with its own blackboard (BehaviorTree.CPP's
 * default) does not see the main tree's keys, so each key a subtree reads is remapped on every call
 * between the main tree and that subtree: k="{k}" on a SubTreePlus and a version-4 SubTree, k="k"
 * on a version-3 SubTree; calls that share the blackboard or remap automatically pass it through
 * as they are.
 */
final class BlackboardKeys {
    private record Read(BehaviorTree tree, String key) {
    }

    private final WovenNodes nodes;

    BlackboardKeys(WovenNodes nodes) {
        this.nodes = nodes;
    }

    /** Remaps on the calls in copies the keys each tree of readers reads. */
    void expose(List<BTModel> copies, Map<BehaviorTree, Set<String>> readers) {
        BTModel primary = copies.get(0);
        String main = primary.getMain_tree_to_execute() != null ? primary.getMain_tree_to_execute()
                : primary.getTrees().isEmpty() ? null : primary.getTrees().get(0).getName();
        List<BehaviorTree> trees = copies.stream().flatMap(c -> c.getTrees().stream()).toList();
        Deque<Read> pending = new ArrayDeque<>();
        readers.forEach((tree, keys) -> keys.forEach(key -> pending.add(new Read(tree, key))));
        Set<String> done = new HashSet<>();
        while (!pending.isEmpty()) {
            Read next = pending.poll();
            BehaviorTree tree = next.tree();
            String key = next.key();
            if (Objects.equals(tree.getName(), main) || !done.add(tree.getName() + "/" + key)) {
                continue;
            }
            for (SubtreeNode call : callsOf(trees, tree)) {
                if (!passesThrough(call) && call.attribute(key) == null) {
                    call.getAttributes().add(nodes.attribute(key,
                            call instanceof SubtreePlus || nodes.isV4() ? "{" + key + "}" : key));
                }
                pending.add(new Read(EcoreUtil2.getContainerOfType(call, BehaviorTree.class), key));
            }
        }
    }

    /** The subtree calls in trees of the tree named as callee (calls match by name: copies and originals alike). */
    private static List<SubtreeNode> callsOf(List<BehaviorTree> trees, BehaviorTree callee) {
        List<SubtreeNode> calls = new ArrayList<>();
        for (BehaviorTree tree : trees) {
            tree.eAllContents().forEachRemaining(o -> {
                if (o instanceof SubtreeNode call) {
                    BehaviorTree target = call.getBehaviorTree();
                    if (Objects.equals(target == null ? null : target.getName(), callee.getName())) {
                        calls.add(call);
                    }
                }
            });
        }
        return calls;
    }

    private boolean passesThrough(SubtreeNode call) {
        if (nodes.isV4()) {
            return isTrue(call.attribute(AUTOREMAP));
        }
        return isTrue(call.attribute(SHARED_BLACKBOARD)) || (call instanceof SubtreePlus && isTrue(call.attribute(V3_AUTOREMAP)));
    }

    /** A literal BehaviorTree.CPP's convertFromString&lt;bool&gt; reads as true. */
    private static boolean isTrue(String value) {
        return value != null && PortType.BOOLEANS.contains(value)
                && (value.equalsIgnoreCase("true") || value.equals("1"));
    }
}
