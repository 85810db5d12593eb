package org.miron.dsl.validation;

import static org.miron.dsl.validation.MironIssueCodes.*;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.validation.Check;
import org.miron.bt.bt.Attribute;
import org.miron.bt.bt.TreeNode;
import org.miron.dsl.bt.BtXPath;
import org.miron.dsl.miron.ArchBinding;
import org.miron.dsl.miron.BehaviorTreeEnumType;
import org.miron.dsl.miron.BtBinding;
import org.miron.dsl.miron.InsertionType;
import org.miron.dsl.miron.MironPackage;
import org.miron.dsl.miron.VariationPoint;
import org.miron.dsl.roqme.DataType;
import org.miron.dsl.roqme.EnumType;
import org.miron.dsl.roqme.NumericType;
import org.miron.dsl.roqme.RoqmeModel;
import org.miron.dsl.roqme.Variable;
import org.miron.dsl.util.Types;

/**
 * Bindings of variation points: enums cannot go to the architecture; a BT binding's XPath,
 * evaluated on the imported .bt file, must select something, and what a numeric varpoint or a
 * before/after insertion needs (attributes, tree nodes).
 */
public class BindingChecks extends CheckSet {

    private static final MironPackage M = MironPackage.eINSTANCE;

    @Check
    public void checkArchBinding(ArchBinding binding) {
        VariationPoint vp = (VariationPoint) binding.eContainer();
        if (Types.dataType(vp) instanceof EnumType) {
            error("enum varpoint '" + vp.getName() + "' cannot be bound to 'arch': only parameters (numbers, booleans) can;"
                    + " bind it to a behavior tree node instead", vp, M.getVariationPoint_Binding(),
                    ENUM_ARCH_BINDING);
        }
    }

    @Check
    public void checkBtBinding(BtBinding binding) {
        VariationPoint vp = (VariationPoint) binding.eContainer();
        DataType type = Types.dataType(vp);
        boolean numeric = type instanceof NumericType;
        if (binding.getXpath() == null) {
            if (numeric) {
                error("numeric varpoint '" + vp.getName() + "' must be bound to a BT node attribute (a port): add an XPath"
                        + " selecting it, e.g. in \"@speed\" " + targetText(binding, 0), binding, M.getBtBinding_Targets(), 0,
                        NUMERIC_BINDING_NEEDS_XPATH);
            }
            return;
        }
        for (int i = 0; i < binding.getTargets().size(); i++) {
            TreeNode target = binding.getTargets().get(i);
            if (target == null || target.eIsProxy()) {
                continue;
            }
            BtXPath.Result result = BtXPath.evaluate(binding.getXpath(), target);
            if (result.error != null) {
                error(result.error, binding, M.getBtBinding_Xpath(), XPATH_ERROR);
                return;
            }
            if (result.selections.isEmpty()) {
                error("XPath '" + binding.getXpath() + "' selects nothing in " + targetText(binding, i)
                        + " of " + target.eResource().getURI().lastSegment(), binding, M.getBtBinding_Xpath(),
                        XPATH_SELECTS_NOTHING);
                continue;
            }
            for (BtXPath.Selection s : result.selections) {
                if (numeric && !s.isAttribute()) {
                    error("numeric varpoint '" + vp.getName() + "' is bound to " + s.describe()
                            + ", which is not an attribute: the XPath must select a port such as @speed",
                            binding, M.getBtBinding_Xpath(), XPATH_NOT_ATTRIBUTE);
                    break;
                } else if (binding.getInsertionType() != InsertionType.IN && !s.isTreeNode()) {
                    error("varpoint '" + vp.getName() + "': '" + binding.getInsertionType().getLiteral()
                            + "' needs tree nodes, but the XPath selects "
                            + s.describe(), binding, M.getBtBinding_Xpath(), XPATH_NOT_TREE_NODE);
                    break;
                } else if (type instanceof BehaviorTreeEnumType && !s.isTreeNode()) {
                    error("varpoint '" + vp.getName() + "' switches behaviour trees, so it must be bound to tree nodes,"
                            + " but the XPath selects " + s.describe(), binding, M.getBtBinding_Xpath(),
                            XPATH_NOT_TREE_NODE);
                    break;
                }
            }
        }
    }

    /**
     * Two varpoints bound 'in' the same node or port would both replace (or set) it: the woven
     * tree could honour only one of them.
     */
    @Check
    public void checkSharedTargets(RoqmeModel model) {
        Map<EObject, VariationPoint> owners = new HashMap<>();
        for (Variable v : model.getVariables()) {
            if (!(v instanceof VariationPoint) || !(((VariationPoint) v).getBinding() instanceof BtBinding)) {
                continue;
            }
            VariationPoint vp = (VariationPoint) v;
            BtBinding binding = (BtBinding) vp.getBinding();
            if (binding.getInsertionType() != InsertionType.IN) {
                continue;
            }
            DataType type = Types.dataType(vp);
            for (int i = 0; i < binding.getTargets().size(); i++) {
                for (EObject target : selected(binding, i)) {
                    // a selection of the wrong kind is reported by checkBtBinding already
                    boolean rightKind = type instanceof NumericType ? target instanceof Attribute
                            : type instanceof BehaviorTreeEnumType ? target instanceof TreeNode : true;
                    if (!rightKind) {
                        continue;
                    }
                    VariationPoint first = owners.putIfAbsent(target, vp);
                    if (first != null && first != vp) {
                        String what = target instanceof Attribute ? "attribute @" + ((Attribute) target).getName()
                                : "node '" + targetText(binding, i) + "'";
                        error("varpoint '" + vp.getName() + "' is bound in the same " + what + " as varpoint '"
                                + first.getName() + "': only one varpoint can replace or set it", binding,
                                binding.getXpath() == null ? M.getBtBinding_Targets() : M.getBtBinding_Xpath(),
                                binding.getXpath() == null ? i : -1, SHARED_TARGET);
                    }
                }
            }
        }
    }

    /** What the i-th target of a binding stands for: the node itself, or what its XPath selects. */
    private static List<EObject> selected(BtBinding binding, int i) {
        TreeNode target = binding.getTargets().get(i);
        if (target == null || target.eIsProxy()) {
            return List.of();
        }
        if (binding.getXpath() == null) {
            return List.of(target);
        }
        List<EObject> result = new ArrayList<>();
        for (BtXPath.Selection s : BtXPath.evaluate(binding.getXpath(), target).selections) {
            if (s.model != null) {
                result.add(s.model);
            }
        }
        return result;
    }

    private String targetText(BtBinding binding, int index) {
        List<INode> nodes = NodeModelUtils
                .findNodesForFeature(binding, M.getBtBinding_Targets());
        return index < nodes.size() ? NodeModelUtils.getTokenText(nodes.get(index)) : "the target";
    }
}
