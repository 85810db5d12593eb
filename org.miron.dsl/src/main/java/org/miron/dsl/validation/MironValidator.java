package org.miron.dsl.validation;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.validation.Check;
import org.miron.bt.bt.TreeNode;
import org.miron.dsl.bt.BtXPath;
import org.miron.dsl.miron.ArchBinding;
import org.miron.dsl.miron.BehaviorTreeEnumType;
import org.miron.dsl.miron.BehaviorTreeLiteral;
import org.miron.dsl.miron.BtBinding;
import org.miron.dsl.miron.Constraint;
import org.miron.dsl.miron.ImpactOnQuality;
import org.miron.dsl.miron.InsertionType;
import org.miron.dsl.miron.MironPackage;
import org.miron.dsl.miron.NumericSampledType;
import org.miron.dsl.miron.QoSProfiledValue;
import org.miron.dsl.miron.Rule;
import org.miron.dsl.miron.SampleValue;
import org.miron.dsl.miron.VariationPoint;
import org.miron.dsl.roqme.BinaryExpression;
import org.miron.dsl.roqme.BinaryOperator;
import org.miron.dsl.roqme.DataType;
import org.miron.dsl.roqme.EnumType;
import org.miron.dsl.roqme.Expression;
import org.miron.dsl.roqme.Import;
import org.miron.dsl.roqme.NumericType;
import org.miron.dsl.roqme.NumericValue;
import org.miron.dsl.roqme.RoqmeModel;
import org.miron.dsl.roqme.RoqmePackage;
import org.miron.dsl.roqme.UnaryExpression;
import org.miron.dsl.roqme.UnaryOperator;
import org.miron.dsl.roqme.VariableRef;
import org.miron.dsl.util.ExprType;
import org.miron.dsl.util.Imports;
import org.miron.dsl.util.Names;
import org.miron.dsl.util.Types;

/**
 * MIRoN's checks on top of RoQME's: presets, samples, impacts, bindings (including the XPath of a
 * BT binding, evaluated on the imported .bt file) and adaptation rules.
 */
public class MironValidator extends AbstractMironValidator {

    private static final MironPackage M = MironPackage.eINSTANCE;
    private static final RoqmePackage R = RoqmePackage.eINSTANCE;
    private static final double GRID_TOLERANCE = 1e-9;

    @Override
    protected List<String> allowedImports() {
        return List.of("bt", "roqme", "miron");
    }

    @Check
    public void checkAliases(RoqmeModel model) {
        Map<String, Import> seen = new HashMap<>();
        for (Import imp : model.getImports()) {
            String alias = Imports.aliasOf(imp);
            if (alias != null && seen.putIfAbsent(alias, imp) != null) {
                error("alias '" + alias + "' is already used by the import at line " + line(seen.get(alias)), imp,
                        M.getImport_Alias());
            }
        }
    }

    // ------------------------------------------------------------------ varpoint types

    @Check
    public void checkPreset(BehaviorTreeEnumType type) {
        List<BehaviorTreeLiteral> presets = new ArrayList<>();
        type.getLiterals().stream().filter(l -> l instanceof BehaviorTreeLiteral && ((BehaviorTreeLiteral) l).isPreset())
                .forEach(l -> presets.add((BehaviorTreeLiteral) l));
        String owner = Names.enumName(type);
        if (presets.isEmpty()) {
            error("behavior tree enum of '" + owner + "' needs exactly one 'preset' literal (the nominal behaviour), found none",
                    type, R.getEnumType_Literals(), 0);
        }
        for (int i = 1; i < presets.size(); i++) {
            error("behavior tree enum of '" + owner + "' needs exactly one 'preset' literal, but '"
                    + presets.get(i).getName() + "' is a second one after '" + presets.get(0).getName() + "'",
                    presets.get(i), M.getBehaviorTreeLiteral_Preset());
        }
    }

    @Check
    public void checkSamples(NumericSampledType type) {
        Set<Double> seen = new HashSet<>();
        for (SampleValue sample : type.getSamples()) {
            if (sample.getValue() == null) {
                continue;
            }
            double v = sample.getValue().getValue();
            if ((type.getLower() != null && v < type.getLower()) || (type.getUpper() != null && v > type.getUpper())) {
                error("sample " + fmt(v) + " of '" + Names.ownerName(type) + "' is outside the declared range " + range(type),
                        sample, M.getSampleValue_Value());
            } else if (type.getPrecision() != null && type.getPrecision() > 0 && !onGrid(v, type)) {
                double base = type.getLower() == null ? 0 : type.getLower();
                error("sample " + fmt(v) + " of '" + Names.ownerName(type) + "' is not on the precision grid " + fmt(base)
                        + " + k*" + fmt(type.getPrecision()),
                        sample, M.getSampleValue_Value());
            } else if (!seen.add(v)) {
                error("sample " + fmt(v) + " of '" + Names.ownerName(type) + "' is declared twice", sample,
                        M.getSampleValue_Value());
            }
        }
    }

    private static boolean onGrid(double v, NumericType type) {
        double base = type.getLower() == null ? 0 : type.getLower();
        double steps = (v - base) / type.getPrecision();
        return Math.abs(steps - Math.rint(steps)) < GRID_TOLERANCE * Math.max(1, Math.abs(steps));
    }

    @Check
    public void checkImpacts(QoSProfiledValue value) {
        Set<EObject> seen = new HashSet<>();
        for (ImpactOnQuality impact : value.getImpacts()) {
            if (impact.getProperty() != null && !impact.getProperty().eIsProxy() && !seen.add(impact.getProperty())) {
                error("impact on '" + impact.getProperty().getName() + "' is declared twice", impact,
                        M.getImpactOnQuality_Property());
            }
        }
    }

    // ------------------------------------------------------------------ bindings

    @Check
    public void checkArchBinding(ArchBinding binding) {
        VariationPoint vp = (VariationPoint) binding.eContainer();
        if (Types.dataType(vp) instanceof EnumType) {
            error("enum varpoint '" + vp.getName() + "' cannot be bound to 'arch': only parameters (numbers, booleans) can;"
                    + " bind it to a behavior tree node instead", vp, M.getVariationPoint_Binding());
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
                        + " selecting it, e.g. in \"@speed\" " + targetText(binding, 0), binding, M.getBtBinding_Targets(), 0);
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
                error(result.error, binding, M.getBtBinding_Xpath());
                return;
            }
            if (result.selections.isEmpty()) {
                error("XPath '" + binding.getXpath() + "' selects nothing in " + targetText(binding, i)
                        + " of " + target.eResource().getURI().lastSegment(), binding, M.getBtBinding_Xpath());
                continue;
            }
            for (BtXPath.Selection s : result.selections) {
                if (numeric && !s.isAttribute()) {
                    error("numeric varpoint '" + vp.getName() + "' is bound to " + s.describe()
                            + ", which is not an attribute: the XPath must select a port such as @" + "speed",
                            binding, M.getBtBinding_Xpath());
                    break;
                } else if (binding.getInsertionType() != InsertionType.IN && !s.isTreeNode()) {
                    error("varpoint '" + vp.getName() + "': '" + binding.getInsertionType().getLiteral()
                            + "' needs tree nodes, but the XPath selects "
                            + s.describe(), binding, M.getBtBinding_Xpath());
                    break;
                }
            }
        }
    }

    private String targetText(BtBinding binding, int index) {
        List<org.eclipse.xtext.nodemodel.INode> nodes = org.eclipse.xtext.nodemodel.util.NodeModelUtils
                .findNodesForFeature(binding, M.getBtBinding_Targets());
        return index < nodes.size() ? org.eclipse.xtext.nodemodel.util.NodeModelUtils.getTokenText(nodes.get(index)) : "the target";
    }

    // ------------------------------------------------------------------ rules

    @Check
    public void checkRule(Rule rule) {
        if (rule.getCondition() != null) {
            ExprType t = Types.typeOf(rule.getCondition().getTerm());
            if (t.kind != ExprType.Kind.BOOLEAN && !t.isUnknown()) {
                error("the condition of rule '" + rule.getName() + "' must be boolean, not " + t, rule.getCondition(),
                        M.getCondition_Term());
            }
        }
        for (Constraint c : rule.getImplies()) {
            ExprType t = Types.typeOf(c.getTerm());
            if (t.kind != ExprType.Kind.BOOLEAN && !t.isUnknown()) {
                error("consequence of rule '" + rule.getName() + "' must be a boolean constraint, not " + t, c,
                        M.getConstraint_Term());
            } else if (!constrainsVarpoint(c)) {
                error("consequence of rule '" + rule.getName() + "' does not constrain any varpoint", c,
                        M.getConstraint_Term());
            }
        }
    }

    /**
     * varpoint = number, in a rule consequence, with a number the varpoint can never take (outside
     * its range or off its precision grid): the rule could never be satisfied.
     */
    @Check
    public void checkConsequenceValue(Constraint c) {
        for (BinaryExpression e : EcoreUtil2.getAllContentsOfType(c, BinaryExpression.class)) {
            checkAssignedValue(e, e.getLeft(), e.getRight());
            checkAssignedValue(e, e.getRight(), e.getLeft());
        }
    }

    private void checkAssignedValue(BinaryExpression e, Expression side,
            Expression value) {
        if (e.getOperator() != BinaryOperator.EQ || !(side instanceof VariableRef)
                || !(((VariableRef) side).getVariable() instanceof VariationPoint)) {
            return;
        }
        Double v = numberOf(value);
        DataType type = Types.dataType(((VariableRef) side).getVariable());
        if (v == null || !(type instanceof NumericType)) {
            return;
        }
        NumericType n = (NumericType) type;
        String name = ((VariableRef) side).getVariable().getName();
        EReference feature = value == e.getRight() ? R.getBinaryExpression_Right() : R.getBinaryExpression_Left();
        if ((n.getLower() != null && v < n.getLower()) || (n.getUpper() != null && v > n.getUpper())) {
            error("varpoint '" + name + "' can never be " + fmt(v) + ": it is outside its range " + range(n), e, feature);
        } else if (n.getPrecision() != null && n.getPrecision() > 0 && !onGrid(v, n)) {
            error("varpoint '" + name + "' can never be " + fmt(v) + ": it is not on its precision grid "
                    + fmt(n.getLower() == null ? 0 : n.getLower()) + " + k*" + fmt(n.getPrecision()), e, feature);
        }
    }

    /** The value of a literal number, possibly negated; null for anything else. */
    private static Double numberOf(Expression e) {
        if (e instanceof NumericValue) {
            return ((NumericValue) e).getValue();
        } else if (e instanceof UnaryExpression
                && ((UnaryExpression) e).getOperator() == UnaryOperator.MINUS) {
            Double inner = numberOf(((UnaryExpression) e).getTerm());
            return inner == null ? null : -inner;
        }
        return null;
    }

    /** Whether a consequence mentions a variation point (unresolved references count as yes). */
    private static boolean constrainsVarpoint(Constraint c) {
        for (VariableRef ref : EcoreUtil2.getAllContentsOfType(c, VariableRef.class)) {
            if (ref.getVariable() == null || ref.getVariable().eIsProxy() || ref.getVariable() instanceof VariationPoint) {
                return true;
            }
        }
        return false;
    }
}
