package org.miron.generator;

import static org.miron.bt.nodes.BuiltinNodes.CASE_PREFIX;
import static org.miron.bt.nodes.BuiltinNodes.VARIABLE;

import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.ControlNode;
import org.miron.bt.bt.Sequence;
import org.miron.bt.bt.SubtreeNode;
import org.miron.bt.bt.Switch;
import org.miron.bt.bt.TreeNode;
import org.miron.dsl.miron.BehaviorTreeLiteral;
import org.miron.dsl.miron.BtBinding;
import org.miron.dsl.miron.InsertionType;

/**
 * Weaves an enum varpoint bound to a tree node (docs/generators.md): a Switch over {vp_sel} with
 * one subtree call per non-preset literal and a default child, the original target for `in`,
 * AlwaysSuccess for `before`/`after`.
 *  - When `in` replaces a subtree call, each variant gets that call's port wiring (its attributes
 *    but name), so a variant sees the same inputs as the nominal subtree.
 *  - `before`/`after` insert the Switch next to the target in its parent; where the parent takes
 *    exactly one child or counts its children (a tree, a decorator, a Switch) target and Switch
 *    are wrapped in a Sequence instead, which keeps the tree loadable and the cases aligned.
 *  - BehaviorTree.CPP stops at Switch6 (the largest SwitchN of the catalogue), so more cases nest
 *    Switches through the default child.
 */
final class VariantSwitches {
    private final WovenNodes nodes;

    VariantSwitches(WovenNodes nodes) {
        this.nodes = nodes;
    }

    void insert(SampledVariationPoint vp, TreeNode target) {
        BtBinding binding = (BtBinding) vp.varpoint.getBinding();
        List<BehaviorTreeLiteral> cases = vp.literals.stream().filter(BehaviorTreeLiteral.class::isInstance)
                .map(BehaviorTreeLiteral.class::cast).filter(l -> !l.isPreset() && l.getReference() != null).toList();
        if (cases.isEmpty()) {
            return; // only the preset: the nominal behaviour needs no Switch
        }
        if (binding.getInsertionType() == InsertionType.IN) {
            // The target moves inside the Switch as its default: park a placeholder there first.
            // A variant replacing a subtree call takes over its port wiring (goal="{ward}"...).
            List<Attribute> wiring = target instanceof SubtreeNode call
                    ? call.getAttributes().stream().filter(a -> !"name".equals(a.getName())).toList()
                    : List.of();
            TreeNode placeholder = nodes.leaf(nodes.factory.createAlwaysSuccess(), "AlwaysSuccess");
            TreeNode choice = switchFor(vp, cases, wiring, placeholder);
            EcoreUtil.replace(target, choice);
            EcoreUtil.replace(placeholder, target);
            return;
        }
        TreeNode choice = switchFor(vp, cases, List.of(), nodes.leaf(nodes.factory.createAlwaysSuccess(), "AlwaysSuccess"));
        boolean before = binding.getInsertionType() == InsertionType.BEFORE;
        EObject parent = target.eContainer();
        if (parent instanceof ControlNode control && !(parent instanceof Switch)) {
            List<TreeNode> children = control.getNodes();
            int index = children.indexOf(target);
            children.add(before ? index : index + 1, choice);
        } else {
            Sequence sequence = nodes.leaf(nodes.factory.createSequence(), "Sequence");
            EcoreUtil.replace(target, sequence);
            if (before) {
                sequence.getNodes().add(choice);
                sequence.getNodes().add(target);
            } else {
                sequence.getNodes().add(target);
                sequence.getNodes().add(choice);
            }
        }
    }

    /** A Switch over the cases whose last child is fallback; nested when there are more than six. */
    private TreeNode switchFor(SampledVariationPoint vp, List<BehaviorTreeLiteral> cases, List<Attribute> wiring,
            TreeNode fallback) {
        int max = nodes.maxSwitchCases();
        if (cases.size() > max) {
            // Leave at least two cases to the inner Switch: there is no Switch1.
            int here = cases.size() - max >= 2 ? max : cases.size() - 2;
            return switchNode(vp, cases.subList(0, here), wiring,
                    switchFor(vp, cases.subList(here, cases.size()), wiring, fallback));
        }
        return switchNode(vp, cases, wiring, fallback);
    }

    private TreeNode switchNode(SampledVariationPoint vp, List<BehaviorTreeLiteral> cases, List<Attribute> wiring,
            TreeNode fallback) {
        // A single case still needs a Switch2: its second case repeats the first, so it is never
        // chosen (the first matching case wins), and its child is an AlwaysFailure.
        boolean padded = cases.size() == 1;
        String tag = "Switch" + (padded ? 2 : cases.size());
        Switch node = nodes.leaf(nodes.factory.createSwitch(), tag);
        node.getAttributes().add(nodes.attribute(nodes.port(tag, VARIABLE), "{" + vp.selection() + "}"));
        for (int i = 0; i < cases.size(); i++) {
            node.getAttributes().add(nodes.attribute(nodes.port(tag, CASE_PREFIX + (i + 1)), cases.get(i).getName()));
        }
        if (padded) {
            node.getAttributes().add(nodes.attribute(nodes.port(tag, CASE_PREFIX + 2), cases.get(0).getName()));
        }
        for (BehaviorTreeLiteral c : cases) {
            SubtreeNode call = nodes.subtree(c.getReference());
            wiring.forEach(a -> call.getAttributes().add(nodes.attribute(a.getName(), a.getValue())));
            node.getNodes().add(call);
        }
        if (padded) {
            node.getNodes().add(nodes.leaf(nodes.factory.createAlwaysFailure(), "AlwaysFailure"));
        }
        node.getNodes().add(fallback);
        return node;
    }
}
