package org.miron.dsl.validation;

import static org.miron.dsl.validation.RoqmeIssueCodes.*;
import static org.miron.dsl.validation.Texts.fmt;
import static org.miron.dsl.validation.Texts.range;

import java.util.List;
import java.util.Map;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.EStructuralFeature;
import org.eclipse.xtext.nodemodel.ICompositeNode;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.validation.Check;
import org.miron.bt.resource.BtXmlFiles;
import org.eclipse.xtext.validation.ComposedChecks;
import org.miron.dsl.roqme.BeliefVariable;
import org.miron.dsl.roqme.Context;
import org.miron.dsl.roqme.DataType;
import org.miron.dsl.roqme.EvidenceAction;
import org.miron.dsl.roqme.Expression;
import org.miron.dsl.roqme.Import;
import org.miron.dsl.roqme.BoundedType;
import org.miron.dsl.roqme.NumericType;
import org.miron.dsl.roqme.NumericValue;
import org.miron.dsl.roqme.Observation;
import org.miron.dsl.roqme.Param;
import org.miron.dsl.roqme.Property;
import org.miron.dsl.roqme.RoqmePackage;
import org.miron.dsl.roqme.Sets;
import org.miron.dsl.roqme.TimeValue;
import org.miron.dsl.roqme.TypedVariable;
import org.miron.dsl.roqme.Var;
import org.miron.dsl.scoping.ImportedResources;
import org.miron.dsl.util.ExprType;
import org.miron.dsl.util.Imports;
import org.miron.dsl.util.Names;
import org.miron.dsl.util.Types;

import com.google.inject.Inject;

/**
 * RoQME's checks: imports, data types, definitions and defaults against declared types, beliefs,
 * times, observations; names, expressions and timers are checked by the composed check sets. MIRoN's
 * validator extends this one, so every RoQME check also runs on MIRoN models.
 */
@ComposedChecks(validators = { NamingChecks.class, ExpressionChecks.class, TimerChecks.class })
public class RoqmeValidator extends AbstractRoqmeValidator {

    private static final RoqmePackage R = RoqmePackage.eINSTANCE;

    @Inject
    private ImportedResources importedResources;

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

    @Override
    protected void handleExceptionDuringValidation(Throwable t) {
        CheckSet.rethrowIfStrict(t);
        super.handleExceptionDuringValidation(t);
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

    // ------------------------------------------------------------------ imports

    @Check
    public void checkImport(Import imp) {
        if (imp.getImportURI() == null || imp.getImportURI().isEmpty()) {
            error("empty import path", imp, R.getImport_ImportURI(), EMPTY_IMPORT);
            return;
        }
        String extension = Imports.uriOf(imp) == null ? null : Imports.uriOf(imp).fileExtension();
        if (extension == null || !allowedImports().contains(extension)) {
            error("cannot import '" + imp.getImportURI() + "': only " + String.join(", ", allowedImports())
                    + " files can be imported here", imp, R.getImport_ImportURI(), IMPORT_NOT_ALLOWED,
                    allowedImports().toArray(new String[0]));
        } else if (Imports.uriOf(imp) != null && Imports.uriOf(imp).equals(imp.eResource().getURI())) {
            error("a file cannot import itself", imp, R.getImport_ImportURI(), SELF_IMPORT);
        } else if ("xml".equals(extension) && !BtXmlFiles.looksLikeBehaviourTree(Imports.uriOf(imp))) {
            error("cannot import '" + imp.getImportURI() + "': it is not a BehaviorTree.CPP tree (its root element is not <root>)",
                    imp, R.getImport_ImportURI(), IMPORT_NOT_ALLOWED, allowedImports().toArray(new String[0]));
        } else if (importedResources.description(imp) == null) {
            error("cannot find imported file '" + imp.getImportURI() + "' (paths are relative to this file)",
                    imp, R.getImport_ImportURI(), IMPORT_NOT_FOUND);
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
                    type, R.getBoundedType_Lower(), EMPTY_RANGE);
        }
        if (type.getPrecision() != null && type.getPrecision() <= 0) {
            error("precision of '" + Names.ownerName(type) + "' must be positive, not " + fmt(type.getPrecision()),
                    type, R.getBoundedType_Precision(), PRECISION_NOT_POSITIVE);
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
                        + range(n), param, R.getTypedVariable_InitializedTo(), DEFAULT_OUT_OF_RANGE);
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
                        + value, sets, R.getSets_Value(), TYPE_MISMATCH);
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
                    + declared, v, feature, ENUM_MISMATCH);
        } else if (!declared.comparableWith(actual)
                && !(declared.kind == ExprType.Kind.EVENT && actual.isEventLike())
                && !(declared.kind == ExprType.Kind.BOOLEAN && actual.kind == ExprType.Kind.EVENT)) {
            error(what + " of '" + v.getName() + "' has type " + actual + ", but '" + v.getName() + "' is declared "
                    + declared, v, feature, TYPE_MISMATCH);
        }
    }

    // ------------------------------------------------------------------ beliefs and time

    @Check
    public void checkBelief(BeliefVariable belief) {
        Double ref = belief.getReference();
        if (ref != null && (ref < 0 || ref > 1)) {
            error("reference of '" + belief.getName() + "' must be in [0,1], not " + fmt(ref), belief,
                    R.getBeliefVariable_Reference(), REFERENCE_OUT_OF_RANGE);
        }
        if (belief instanceof Property) {
            Property p = (Property) belief;
            if (p.getInitializedTo() != null && !Types.typeOf(p.getInitializedTo()).isNumeric()) {
                error("property '" + p.getName() + "' is a number in [0,1], but its definition has type "
                        + Types.typeOf(p.getInitializedTo()), p, R.getProperty_InitializedTo(), TYPE_MISMATCH);
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
            error("survival of " + owner + " must be positive, not " + fmt(time.getValue()), time, R.getTimeValue_Value(),
                    SURVIVAL_NOT_POSITIVE);
        }
    }

    @Check
    public void checkObservation(Observation observation) {
        ExprType t = Types.typeOf(observation.getPattern());
        if (!t.isEventLike()) {
            error("the pattern of observation '" + observation.getName() + "' must be boolean or an event, not " + t,
                    observation, R.getObservation_Pattern(), PATTERN_TYPE);
        }
    }
}
