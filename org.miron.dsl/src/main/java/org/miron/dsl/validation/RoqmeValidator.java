package org.miron.dsl.validation;

import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.eclipse.emf.common.util.URI;
import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EReference;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.naming.IQualifiedNameConverter;
import org.eclipse.xtext.naming.QualifiedName;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.resource.IEObjectDescription;
import org.eclipse.xtext.scoping.IScopeProvider;
import org.eclipse.xtext.validation.Check;
import org.eclipse.xtext.validation.CheckType;
import org.miron.dsl.naming.DslQualifiedNameProvider;
import org.miron.dsl.roqme.BeliefVariable;
import org.miron.dsl.roqme.BinaryExpression;
import org.miron.dsl.roqme.BoundedType;
import org.miron.dsl.roqme.ConditionalExpression;
import org.miron.dsl.roqme.Context;
import org.miron.dsl.roqme.DataType;
import org.miron.dsl.roqme.EnumLiteral;
import org.miron.dsl.roqme.EnumType;
import org.miron.dsl.roqme.EnumValue;
import org.miron.dsl.roqme.EvidenceAction;
import org.miron.dsl.roqme.Expression;
import org.miron.dsl.roqme.FunctionCall;
import org.miron.dsl.roqme.Import;
import org.miron.dsl.roqme.NumericType;
import org.miron.dsl.roqme.NumericValue;
import org.miron.dsl.roqme.Observation;
import org.miron.dsl.roqme.Param;
import org.miron.dsl.roqme.Property;
import org.miron.dsl.roqme.RangeExpression;
import org.miron.dsl.roqme.RepeatExpression;
import org.miron.dsl.roqme.RoqmeModel;
import org.miron.dsl.roqme.RoqmePackage;
import org.miron.dsl.roqme.Sets;
import org.miron.dsl.roqme.TimeValue;
import org.miron.dsl.roqme.Timer;
import org.miron.dsl.roqme.TypedVariable;
import org.miron.dsl.roqme.UnaryExpression;
import org.miron.dsl.roqme.Var;
import org.miron.dsl.roqme.WhileExpression;
import org.miron.dsl.util.ExprType;
import org.miron.dsl.util.Imports;
import org.miron.dsl.util.Names;
import org.miron.dsl.util.Types;

import com.google.inject.Inject;

/**
 * RoQME's own checks: names, ranges, beliefs, imports, and the type checking of expressions.
 * MIRoN's validator extends this one, so every check here also runs on MIRoN models.
 */
public class RoqmeValidator extends AbstractRoqmeValidator {

    private static final RoqmePackage R = RoqmePackage.eINSTANCE;
    /** Allowed argument counts of the built-in functions: {min, max}. */
    private static final Map<String, int[]> ARITY = new HashMap<>();
    static {
        for (String f : List.of("sqrt", "exp", "abs", "update", "period", "first", "last", "size", "isEmpty", "schedule")) {
            ARITY.put(f, new int[] { 1, 1 });
        }
        for (String f : List.of("avg", "min", "max", "count", "sum", "decreasing", "increasing", "stable", "eventWhen")) {
            ARITY.put(f, new int[] { 1, 2 });
        }
        for (String f : List.of("pow", "at", "includes")) {
            ARITY.put(f, new int[] { 2, 2 });
        }
    }

    @Inject
    private IScopeProvider scopeProvider;

    @Inject
    private IQualifiedNameConverter nameConverter;

    /**
     * Elements with a syntax error inside are not checked: their model is incomplete, and a
     * check would only repeat the syntax error in confusing terms (a missing number reads as 0).
     */
    @Override
    protected boolean isResponsible(Map<Object, Object> context, EObject object) {
        if (object.eResource() != null && !object.eResource().getErrors().isEmpty() && hasSyntaxError(object)) {
            return false;
        }
        return super.isResponsible(context, object);
    }

    private static boolean hasSyntaxError(EObject object) {
        ICompositeNode node = NodeModelUtils.getNode(object);
        if (node == null) {
            return false;
        }
        for (INode n : node.getAsTreeIterable()) {
            if (n.getSyntaxErrorMessage() != null) {
                return true;
            }
        }
        return false;
    }

    // ------------------------------------------------------------------ names

    @Check
    public void checkUniqueNames(RoqmeModel model) {
        Map<String, EObject> seen = new HashMap<>();
        for (EObject obj : model.eContents()) {
            String name = DslQualifiedNameProvider.nameOf(obj);
            if (name == null) {
                continue;
            }
            EObject first = seen.putIfAbsent(name, obj);
            if (first != null) {
                error("duplicate name '" + name + "': already declared at line " + line(first),
                        obj, obj.eClass().getEStructuralFeature("name"));
            }
        }
    }

    @Check
    public void checkEnumLiterals(EnumType type) {
        Set<String> seen = new LinkedHashSet<>();
        for (EnumLiteral literal : type.getLiterals()) {
            if (literal.getName() != null && !seen.add(literal.getName())) {
                error("enum literal '" + literal.getName() + "' is repeated in " + Names.enumName(type),
                        literal, R.getEnumLiteral_Name());
            }
        }
    }

    /** Every cross-reference whose name matches several elements (e.g. two imports exposing it). */
    @Check(CheckType.NORMAL)
    public void checkAmbiguousReferences(EObject obj) {
        for (EReference ref : obj.eClass().getEAllReferences()) {
            if (ref.isContainment() || ref.isContainer() || ref.isDerived() || ref.isTransient()) {
                continue;
            }
            List<INode> nodes = NodeModelUtils.findNodesForFeature(obj, ref);
            for (int i = 0; i < nodes.size(); i++) {
                String text = NodeModelUtils.getTokenText(nodes.get(i));
                QualifiedName name = nameConverter.toQualifiedName(text);
                Set<URI> targets = new LinkedHashSet<>();
                for (IEObjectDescription d : scopeProvider.getScope(obj, ref).getElements(name)) {
                    targets.add(d.getEObjectURI());
                }
                if (targets.size() > 1) {
                    StringBuilder where = new StringBuilder();
                    for (URI uri : targets) {
                        where.append(where.length() == 0 ? "" : ", ").append(uri.trimFragment().lastSegment());
                    }
                    error("ambiguous reference '" + text + "': " + targets.size() + " elements have this name (in "
                            + where + "); import one of the files with an alias", obj, ref, ref.isMany() ? i : -1);
                }
            }
        }
    }

    // ------------------------------------------------------------------ imports

    @Check
    public void checkImport(Import imp) {
        if (imp.getImportURI() == null || imp.getImportURI().isEmpty()) {
            error("empty import path", imp, R.getImport_ImportURI());
            return;
        }
        String extension = Imports.uriOf(imp) == null ? null : Imports.uriOf(imp).fileExtension();
        if (extension == null || !allowedImports().contains(extension)) {
            error("cannot import '" + imp.getImportURI() + "': only " + String.join(", ", allowedImports())
                    + " files can be imported here", imp, R.getImport_ImportURI());
        } else if (Imports.uriOf(imp) != null && Imports.uriOf(imp).equals(imp.eResource().getURI())) {
            error("a file cannot import itself", imp, R.getImport_ImportURI());
        } else if (Imports.load(imp) == null) {
            error("cannot find imported file '" + imp.getImportURI() + "' (paths are relative to this file)",
                    imp, R.getImport_ImportURI());
        }
    }

    /** File extensions an import may name. */
    protected List<String> allowedImports() {
        return List.of("roqme");
    }

    // ------------------------------------------------------------------ data types

    @Check
    public void checkBounds(BoundedType type) {
        Double lo = type.getLower();
        Double hi = type.getUpper();
        if (lo != null && hi != null && lo >= hi) {
            error("empty range of '" + Names.ownerName(type) + "': lower bound " + fmt(lo)
                    + " must be less than upper bound " + fmt(hi),
                    type, R.getBoundedType_Lower());
        }
        if (type.getPrecision() != null && type.getPrecision() <= 0) {
            error("precision of '" + Names.ownerName(type) + "' must be positive, not " + fmt(type.getPrecision()),
                    type, R.getBoundedType_Precision());
        }
    }

    @Check
    public void checkParamDefault(Param param) {
        checkAssignable(param, param.getInitializedTo(), R.getTypedVariable_InitializedTo(), "default value");
        DataType type = Types.dataType(param);
        if (type instanceof NumericType && param.getInitializedTo() instanceof NumericValue) {
            double v = ((NumericValue) param.getInitializedTo()).getValue();
            NumericType n = (NumericType) type;
            if ((n.getLower() != null && v < n.getLower()) || (n.getUpper() != null && v > n.getUpper())) {
                error("default value " + fmt(v) + " of '" + param.getName() + "' is outside its range "
                        + range(n), param, R.getTypedVariable_InitializedTo());
            }
        }
    }

    @Check
    public void checkDerived(Context context) {
        checkAssignable(context, context.getInitializedTo(), R.getTypedVariable_InitializedTo(), "derivation");
    }

    @Check
    public void checkVar(Var var) {
        checkAssignable(var, var.getInitializedTo(), R.getTypedVariable_InitializedTo(), "definition");
    }

    @Check
    public void checkSets(Sets sets) {
        if (sets.getVariable() != null && !sets.getVariable().eIsProxy()) {
            ExprType target = Types.typeOf(sets.getVariable());
            ExprType value = Types.typeOf(sets.getValue());
            if (!target.comparableWith(value)) {
                error("cannot set '" + sets.getVariable().getName() + "' (" + target + ") to a value of type "
                        + value, sets, R.getSets_Value());
            }
        }
    }

    /** A typed variable's expression must produce values of its declared type. */
    private void checkAssignable(TypedVariable v, Expression e, EStructuralFeature feature, String what) {
        if (e == null) {
            return;
        }
        ExprType declared = Types.typeOf(v.getDeclaration());
        ExprType actual = Types.typeOf(e);
        if (declared.kind == ExprType.Kind.ENUM && actual.kind == ExprType.Kind.ENUM && declared.enumType != actual.enumType) {
            error(what + " of '" + v.getName() + "' is a literal of " + actual + ", but '" + v.getName() + "' is "
                    + declared, v, feature);
        } else if (!declared.comparableWith(actual)
                && !(declared.kind == ExprType.Kind.EVENT && actual.isEventLike())
                && !(declared.kind == ExprType.Kind.BOOLEAN && actual.kind == ExprType.Kind.EVENT)) {
            error(what + " of '" + v.getName() + "' has type " + actual + ", but '" + v.getName() + "' is declared "
                    + declared, v, feature);
        }
    }

    // ------------------------------------------------------------------ beliefs and time

    @Check
    public void checkBelief(BeliefVariable belief) {
        Double ref = belief.getReference();
        if (ref != null && (ref < 0 || ref > 1)) {
            error("reference of '" + belief.getName() + "' must be in [0,1], not " + fmt(ref), belief,
                    R.getBeliefVariable_Reference());
        }
        if (belief instanceof Property) {
            Property p = (Property) belief;
            if (p.getInitializedTo() != null && !Types.typeOf(p.getInitializedTo()).isNumeric()) {
                error("property '" + p.getName() + "' is a number in [0,1], but its definition has type "
                        + Types.typeOf(p.getInitializedTo()), p, R.getProperty_InitializedTo());
            }
        }
    }

    @Check
    public void checkTimeValue(TimeValue time) {
        EStructuralFeature feature = time.eContainingFeature();
        boolean survival = feature == R.getBeliefVariable_Survival() || feature == R.getEvidenceAction_Survival();
        if (survival && time.getValue() <= 0) {
            String owner = time.eContainer() instanceof EvidenceAction
                    ? "the evidence in '" + Names.ownerName(time) + "'"
                    : "'" + Names.ownerName(time) + "'";
            error("survival of " + owner + " must be positive, not " + fmt(time.getValue()), time, R.getTimeValue_Value());
        }
    }

    @Check
    public void checkTimer(Timer timer) {
        if (timer.getCondition() != null && !Types.typeOf(timer.getCondition()).isEventLike()) {
            error("timer '" + timer.getName() + "' needs a boolean or event pattern, not "
                    + Types.typeOf(timer.getCondition()), timer, R.getTimer_Condition());
        }
    }

    @Check
    public void checkObservation(Observation observation) {
        ExprType t = Types.typeOf(observation.getPattern());
        if (!t.isEventLike()) {
            error("the pattern of observation '" + observation.getName() + "' must be boolean or an event, not " + t,
                    observation, R.getObservation_Pattern());
        }
    }

    @Check
    public void checkEvidence(EvidenceAction action) {
        // nothing beyond the linking of the belief and the survival time, checked elsewhere
    }

    // ------------------------------------------------------------------ expressions

    @Check
    public void checkBinary(BinaryExpression e) {
        ExprType l = Types.typeOf(e.getLeft());
        ExprType r = Types.typeOf(e.getRight());
        String op = e.getOperator().getLiteral();
        switch (e.getOperator()) {
        case EQ:
        case NE:
            checkComparable(e, l, r, op);
            break;
        case LT:
        case GT:
        case LE:
        case GE:
            // booleans are ordered too (false < true): real models write "charging > false"
            if (l.kind == ExprType.Kind.BOOLEAN && r.kind == ExprType.Kind.BOOLEAN) {
                break;
            }
            if (!l.isNumeric()) {
                error("'" + op + "' needs numbers, but the left operand is " + l, e, R.getBinaryExpression_Left());
            } else if (!r.isNumeric()) {
                error("'" + op + "' needs numbers, but the right operand is " + r, e, R.getBinaryExpression_Right());
            }
            break;
        case PLUS:
        case MINUS:
        case TIMES:
        case DIVIDE:
            if (!l.isNumeric()) {
                error("'" + op + "' needs numbers, but the left operand is " + l, e, R.getBinaryExpression_Left());
            } else if (!r.isNumeric()) {
                error("'" + op + "' needs numbers, but the right operand is " + r, e, R.getBinaryExpression_Right());
            }
            break;
        case LOGICAL_AND:
        case LOGICAL_OR:
            if (!l.isLogical()) {
                error("'" + op + "' needs boolean or event operands, but the left one is " + l, e, R.getBinaryExpression_Left());
            } else if (!r.isLogical()) {
                error("'" + op + "' needs boolean or event operands, but the right one is " + r, e, R.getBinaryExpression_Right());
            }
            break;
        default: // event operators: or, and, ->
            if (!l.isEventLike()) {
                error("'" + op + "' needs events, booleans or enums, but the left operand is " + l, e, R.getBinaryExpression_Left());
            } else if (!r.isEventLike()) {
                error("'" + op + "' needs events, booleans or enums, but the right operand is " + r, e, R.getBinaryExpression_Right());
            }
        }
    }

    private void checkComparable(BinaryExpression e, ExprType l, ExprType r, String op) {
        if (l.comparableWith(r)) {
            return;
        }
        if (l.kind == ExprType.Kind.ENUM && r.kind == ExprType.Kind.ENUM) {
            Expression literalSide = e.getRight() instanceof EnumValue ? e.getRight() : e.getLeft();
            Expression other = literalSide == e.getRight() ? e.getLeft() : e.getRight();
            String literal = literalSide instanceof EnumValue ? text(literalSide) : "value of " + Types.typeOf(literalSide);
            error("cannot compare '" + text(other) + "' (" + Types.typeOf(other) + ") with '" + literal
                    + "', a literal of another enum (" + Types.typeOf(literalSide) + ")", e,
                    literalSide == e.getRight() ? R.getBinaryExpression_Right() : R.getBinaryExpression_Left());
        } else {
            error("cannot compare '" + text(e.getLeft()) + "' (" + l + ") with '" + text(e.getRight()) + "' (" + r
                    + ") using '" + op + "'", e, R.getBinaryExpression_Right());
        }
    }

    @Check
    public void checkUnary(UnaryExpression e) {
        ExprType t = Types.typeOf(e.getTerm());
        switch (e.getOperator()) {
        case MINUS:
            if (!t.isNumeric()) {
                error("'-' needs a number, not " + t, e, R.getUnaryExpression_Term());
            }
            break;
        case LOGICAL_NOT:
            if (!t.isLogical()) {
                error("'!' needs a boolean or event operand, not " + t, e, R.getUnaryExpression_Term());
            }
            break;
        default: // not, once
            if (!t.isEventLike()) {
                error("'" + e.getOperator().getLiteral() + "' needs an event, boolean or enum operand, not " + t, e,
                        R.getUnaryExpression_Term());
            }
        }
    }

    @Check
    public void checkConditional(ConditionalExpression e) {
        ExprType c = Types.typeOf(e.getCondition());
        if (!c.isLogical()) {
            error("the condition of '?:' must be boolean, not " + c, e, R.getConditionalExpression_Condition());
        }
        ExprType a = Types.typeOf(e.getIfTrue());
        ExprType b = Types.typeOf(e.getIfFalse());
        if (!a.comparableWith(b)) {
            error("both branches of '?:' must have the same type, not " + a + " and " + b, e,
                    R.getConditionalExpression_IfFalse());
        }
    }

    @Check
    public void checkWhile(WhileExpression e) {
        if (!Types.typeOf(e.getCondition()).isLogical()) {
            error("the condition of 'while' must be boolean, not " + Types.typeOf(e.getCondition()), e,
                    R.getWhileExpression_Condition());
        }
    }

    @Check
    public void checkRepeat(RepeatExpression e) {
        if (e.getTimes() <= 0) {
            error("repeat count must be positive, not " + e.getTimes() + " (in '" + Names.ownerName(e) + "')", e,
                    R.getRepeatExpression_Times());
        }
    }

    @Check
    public void checkRange(RangeExpression e) {
        if (e.getMin() > e.getMax()) {
            error("range(" + e.getMin() + ", " + e.getMax() + ") is empty: the minimum exceeds the maximum", e,
                    R.getRangeExpression_Min());
        }
    }

    @Check
    public void checkFunctionCall(FunctionCall call) {
        int[] arity = ARITY.get(call.getFunction());
        int n = call.getArgs().size();
        if (arity != null && (n < arity[0] || n > arity[1])) {
            String expected = arity[0] == arity[1] ? String.valueOf(arity[0]) : arity[0] + " or " + arity[1];
            error("function '" + call.getFunction() + "' takes " + expected + " argument(s), not " + n, call,
                    R.getFunctionCall_Function());
        }
    }

    // ------------------------------------------------------------------ helpers

    protected static String fmt(double d) {
        return d == Math.rint(d) && Math.abs(d) < 1e15 ? String.valueOf((long) d) : String.valueOf(d);
    }

    protected static String range(org.miron.dsl.roqme.BoundedType t) {
        return "(" + (t.getLower() == null ? "-inf" : fmt(t.getLower())) + ":"
                + (t.getUpper() == null ? "+inf" : fmt(t.getUpper())) + ")";
    }

    /** The line of an element's name (not of its documentation comment). */
    protected static int line(EObject obj) {
        EStructuralFeature name = obj.eClass().getEStructuralFeature("name");
        List<INode> nodes = name == null ? List.of() : NodeModelUtils.findNodesForFeature(obj, name);
        INode node = nodes.isEmpty() ? NodeModelUtils.getNode(obj) : nodes.get(0);
        return node == null ? 0 : node.getStartLine();
    }

    /** The source text of an element, for messages. */
    protected static String text(EObject obj) {
        INode node = NodeModelUtils.getNode(obj);
        return node == null ? String.valueOf(EcoreUtil.getURI(obj)) : NodeModelUtils.getTokenText(node);
    }
}
