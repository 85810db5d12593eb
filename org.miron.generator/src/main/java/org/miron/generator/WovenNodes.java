package org.miron.generator;

import static org.miron.bt.nodes.BuiltinNodes.FAILURE_COUNT;
import static org.miron.bt.nodes.BuiltinNodes.FAILURE_THRESHOLD;
import static org.miron.bt.nodes.BuiltinNodes.SUCCESS_COUNT;
import static org.miron.bt.nodes.BuiltinNodes.SUCCESS_THRESHOLD;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.eclipse.emf.ecore.util.EcoreUtil;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.BtFactory;
import org.miron.bt.bt.SubtreeNode;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.nodes.NodeCatalogue;
import org.miron.bt.nodes.NodeModel;

/**
 * Makes the nodes the weaver adds, in the idioms of the BehaviorTree.CPP version being written
 * (v3: SubTreePlus, success_threshold; v4: SubTree, success_count). Every built-in tag and port it
 * writes is looked up in the catalogue of built-in nodes for that version (org.miron.bt.nodes), so
 * writing one the version lacks fails at once rather than in the executor.
 */
final class WovenNodes {
    private static final Pattern SWITCH = Pattern.compile("Switch(\\d+)");

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

    /** The node with its tag, a built-in of the format being written. */
    <T extends TreeNode> T leaf(T node, String tag) {
        builtin(tag);
        node.setTag(tag);
        return node;
    }

    /** The catalogue entry of a built-in the weaver writes; one the format lacks is a programming error. */
    NodeModel builtin(String tag) {
        return NodeCatalogue.builtin(tag, format).orElseThrow(() -> new IllegalStateException(
                "the weaver writes " + tag + ", which is not a BehaviorTree.CPP " + format + " built-in"));
    }

    /** A port of a built-in in the format being written, by its catalogue name. */
    String port(String tag, String name) {
        return builtin(tag).port(name, format).orElseThrow(() -> new IllegalStateException(
                "the weaver writes " + tag + "." + name + ", which BehaviorTree.CPP " + format + " lacks")).name();
    }

    /** The most cases one Switch takes: the largest N with a SwitchN in the format (6 in both). */
    int maxSwitchCases() {
        int max = 0;
        for (String tag : NodeCatalogue.tags(format)) {
            Matcher m = SWITCH.matcher(tag);
            if (m.matches()) {
                max = Math.max(max, Integer.parseInt(m.group(1)));
            }
        }
        return max;
    }

    /** A subtree call with its own blackboard: v3 SubTreePlus (which remaps with {key}), v4 SubTree. */
    SubtreeNode subtree(BehaviorTree tree) {
        SubtreeNode node = isV4() ? factory.createSubtree() : factory.createSubtreePlus();
        leaf(node, isV4() ? "SubTree" : "SubTreePlus");
        BehaviorTree copy = (BehaviorTree) copier.get(tree);
        node.setBehaviorTree(copy != null ? copy : tree);
        return node;
    }

    /** The attribute naming how many children must succeed (v3 success_threshold, v4 success_count). */
    String successCount() {
        return port("Parallel", isV4() ? SUCCESS_COUNT : SUCCESS_THRESHOLD);
    }

    /** The attribute naming how many children may fail (v3 failure_threshold, v4 failure_count). */
    String failureCount() {
        return port("Parallel", isV4() ? FAILURE_COUNT : FAILURE_THRESHOLD);
    }
}
