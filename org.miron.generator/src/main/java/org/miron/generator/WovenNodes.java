package org.miron.generator;

import org.eclipse.emf.ecore.util.EcoreUtil;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.BtFactory;
import org.miron.bt.bt.SubtreeNode;
import org.miron.bt.bt.TreeNode;

/**
 * Makes the nodes the weaver adds, in the idioms of the BehaviorTree.CPP version being written
 * (v3: SubTreePlus, success_threshold; v4: SubTree, success_count).
 */
final class WovenNodes {
    final BtFactory factory = BtFactory.eINSTANCE;
    /** The format being written, 3 or 4. */
    private final int format;
    /** Originals to their copies in the woven tree: variant calls point at the copies when there are. */
    private final EcoreUtil.Copier copier;

    WovenNodes(int format, EcoreUtil.Copier copier) {
        this.format = format;
        this.copier = copier;
    }

    int format() {
        return format;
    }

    boolean isV4() {
        return format == 4;
    }

    Attribute attribute(String name, String value) {
        Attribute a = factory.createAttribute();
        a.setName(name);
        a.setValue(value);
        return a;
    }

    <T extends TreeNode> T leaf(T node, String tag) {
        node.setTag(tag);
        return node;
    }

    /** A subtree call with its own blackboard: v3 SubTreePlus (which remaps with {key}), v4 SubTree. */
    SubtreeNode subtree(BehaviorTree tree) {
        SubtreeNode node = isV4() ? factory.createSubtree() : factory.createSubtreePlus();
        node.setTag(isV4() ? "SubTree" : "SubTreePlus");
        BehaviorTree copy = (BehaviorTree) copier.get(tree);
        node.setBehaviorTree(copy != null ? copy : tree);
        return node;
    }

    /** The attribute naming how many children must succeed (v3 success_threshold, v4 success_count). */
    String successCount() {
        return isV4() ? "success_count" : "success_threshold";
    }

    /** The attribute naming how many children may fail (v3 failure_threshold, v4 failure_count). */
    String failureCount() {
        return isV4() ? "failure_count" : "failure_threshold";
    }
}
