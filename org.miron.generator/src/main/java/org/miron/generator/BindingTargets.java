package org.miron.generator;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

import org.eclipse.emf.ecore.EObject;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.SubtreeNode;
import org.miron.bt.bt.TreeNode;
import org.miron.bt.util.BtAttributes;
import org.miron.dsl.bt.BtXPath;
import org.miron.dsl.miron.BehaviorTreeLiteral;
import org.miron.dsl.miron.BtBinding;

/** What a varpoint's BT binding points at: tree nodes, or node attributes (ports). */
public final class BindingTargets {
    private BindingTargets() {
    }

    /** The tree nodes or attributes a BT binding selects (its XPath is applied to each target). */
    public static List<EObject> select(SampledVariationPoint vp, List<GenerationError> errors) {
        BtBinding binding = (BtBinding) vp.varpoint.getBinding();
        List<EObject> result = new ArrayList<>();
        for (TreeNode target : binding.getTargets()) {
            if (target.eIsProxy()) {
                continue;
            }
            if (binding.getXpath() == null) {
                result.add(target);
                continue;
            }
            BtXPath.Result selection = BtXPath.evaluate(binding.getXpath(), target);
            if (selection.error != null) {
                errors.add(new GenerationError(binding, selection.error));
            }
            for (BtXPath.Selection s : selection.selections) {
                if (s.model instanceof TreeNode || s.model instanceof Attribute) {
                    result.add(s.model);
                }
            }
        }
        boolean nodes = result.stream().anyMatch(TreeNode.class::isInstance);
        if (!vp.isEnum() && nodes) {
            String example = binding.getTargets().isEmpty() ? ""
                    : Objects.toString(binding.getTargets().get(0).getName(), "");
            errors.add(new GenerationError(binding, "numeric varpoint '" + vp.name
                    + "' can only be bound to node attributes (ports), e.g. in \"@speed\" " + example));
        }
        if (vp.isEnum() && nodes && !vp.literals.stream().allMatch(BehaviorTreeLiteral.class::isInstance)) {
            errors.add(new GenerationError(binding, "enum varpoint '" + vp.name
                    + "' is bound to a tree node, so each literal must name a behavior tree or be the preset"));
        }
        return result;
    }

    /** How a node is named in the IO map: its name, else its ID, else its tag. */
    public static String nameOf(EObject target) {
        if (target instanceof Attribute) {
            return nameOf(target.eContainer());
        }
        if (target instanceof SubtreeNode call) {
            String name = BtAttributes.value(call.getAttributes(), "name");
            if (name != null) {
                return name;
            }
            String tree = call.getBehaviorTree() == null ? null : call.getBehaviorTree().getName();
            return tree != null ? tree : call.getTag();
        }
        if (target instanceof TreeNode node) {
            String name = BtAttributes.value(node.getAttributes(), "name");
            if (name == null) {
                name = BtAttributes.value(node.getAttributes(), "ID");
            }
            return name != null ? name : node.getTag();
        }
        return "?";
    }
}
