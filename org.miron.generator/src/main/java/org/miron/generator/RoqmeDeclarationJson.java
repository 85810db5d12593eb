package org.miron.generator;

import java.math.BigDecimal;
import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.miron.dsl.roqme.Action;
import org.miron.dsl.roqme.BeliefVariable;
import org.miron.dsl.roqme.BooleanType;
import org.miron.dsl.roqme.BoundedType;
import org.miron.dsl.roqme.Clears;
import org.miron.dsl.roqme.Context;
import org.miron.dsl.roqme.DataType;
import org.miron.dsl.roqme.EnumLiteral;
import org.miron.dsl.roqme.EnumType;
import org.miron.dsl.roqme.EventType;
import org.miron.dsl.roqme.EvidenceAction;
import org.miron.dsl.roqme.Expression;
import org.miron.dsl.roqme.FunctionCall;
import org.miron.dsl.roqme.NumericType;
import org.miron.dsl.roqme.Observation;
import org.miron.dsl.roqme.Param;
import org.miron.dsl.roqme.Property;
import org.miron.dsl.roqme.Reinforces;
import org.miron.dsl.roqme.Sets;
import org.miron.dsl.roqme.StringValue;
import org.miron.dsl.roqme.TimeType;
import org.miron.dsl.roqme.TimeValue;
import org.miron.dsl.roqme.Timer;
import org.miron.dsl.roqme.TimerAction;
import org.miron.dsl.roqme.TypeReference;
import org.miron.dsl.roqme.TypedVariable;
import org.miron.dsl.roqme.Undermines;
import org.miron.dsl.roqme.Var;
import org.miron.dsl.roqme.util.RoqmeSwitch;
import org.miron.dsl.util.DocComments;
import org.miron.dsl.util.Evidence;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * The runtime model's declarations, actions and types (docs/roqme-model.md) from roqme.ecore's
 * switch: each declaration case adds its node to the array of its kind. A class without a case
 * reaches {@link #defaultCase} and is refused as unsupported.
 */
final class RoqmeDeclarationJson extends RoqmeSwitch<ObjectNode> {
    private static final JsonNodeFactory JSON = JsonNodeFactory.instance;

    private final RoqmeDeclarations declarations;
    private final RoqmeExpressionJson expressions;
    private final List<GenerationError> errors;
    private final ObjectNode root;

    /** Writes into root's arrays contexts, params, vars, timers, beliefs and observations. */
    RoqmeDeclarationJson(ObjectNode root, RoqmeDeclarations declarations, List<GenerationError> errors) {
        this.root = root;
        this.declarations = declarations;
        this.errors = errors;
        this.expressions = new RoqmeExpressionJson(declarations, errors);
        for (String kind : List.of("contexts", "params", "vars", "timers", "beliefs", "observations")) {
            root.putArray(kind);
        }
    }

    private ArrayNode array(String kind) {
        return (ArrayNode) root.get(kind);
    }

    // ------------------------------------------------------------------ declarations

    @Override
    public ObjectNode caseContext(Context c) {
        ObjectNode node = variable(c);
        if (c.getInitializedTo() != null) {
            node.set("derived", expressions.expr(c.getInitializedTo()));
        }
        array("contexts").add(node);
        return node;
    }

    @Override
    public ObjectNode caseParam(Param p) {
        ObjectNode node = variable(p);
        node.set("default", expressions.expr(p.getInitializedTo())); // a Value, or null when omitted
        array("params").add(node);
        return node;
    }

    @Override
    public ObjectNode caseVar(Var v) {
        ObjectNode node = variable(v);
        node.set("init", expressions.expr(v.getInitializedTo()));
        array("vars").add(node);
        return node;
    }

    @Override
    public ObjectNode caseTimer(Timer t) {
        ObjectNode node = header(t);
        Expression def = t.getDefinition();
        if (def instanceof TimeValue period) {
            node.put("periodMs", Numbers.clean(Evidence.exactMillis(period)));
            node.putNull("schedule");
        } else if (def instanceof FunctionCall call && "schedule".equals(call.getFunction()) && call.getArgs().size() == 1
                && call.getArgs().get(0) instanceof StringValue cron) {
            node.putNull("periodMs");
            node.put("schedule", cron.getValue());
        } else {
            errors.add(new GenerationError(def == null ? t : def, "the period of timer '" + t.getName()
                    + "' must be a time literal such as 10 minutes, or schedule(\"cron\"): the runtime model holds "
                    + "no period computed at run time", RoqmeRuntimeModel.TIMER_PERIOD));
        }
        node.put("offsetMs", t.getOffset() == null ? BigDecimal.ZERO : Numbers.clean(Evidence.exactMillis(t.getOffset())));
        node.put("onetime", t.isOnetime());
        node.put("paused", t.isPaused());
        array("timers").add(node);
        return node;
    }

    @Override
    public ObjectNode caseProperty(Property p) {
        ObjectNode node = belief(p, "property");
        node.set("expr", expressions.expr(p.getInitializedTo()));
        if (p.getDeclaration() != null) {
            node.set("type", doSwitch(p.getDeclaration()));
        }
        return node;
    }

    @Override
    public ObjectNode caseBeliefVariable(BeliefVariable b) {
        ObjectNode node = belief(b, "beliefvar");
        node.putNull("expr");
        return node;
    }

    @Override
    public ObjectNode caseObservation(Observation o) {
        ObjectNode node = header(o);
        node.set("pattern", expressions.expr(o.getPattern()));
        ArrayNode actions = node.putArray("actions");
        for (Action action : o.getActions()) {
            actions.add(doSwitch(action));
        }
        String doc = DocComments.plain(o.getDocumentation());
        if (doc != null) {
            node.put("doc", doc);
        }
        array("observations").add(node);
        return node;
    }

    private ObjectNode header(EObject declaration) {
        ObjectNode node = JSON.objectNode();
        node.put("id", declarations.id(declaration));
        node.put("name", RoqmeDeclarations.name(declaration));
        node.put("namespace", RoqmeDeclarations.namespace(declaration));
        node.put("at", RoqmeDeclarations.at(declaration));
        return node;
    }

    private ObjectNode variable(TypedVariable v) {
        ObjectNode node = header(v);
        node.set("type", doSwitch(v.getDeclaration()));
        return node;
    }

    private ObjectNode belief(BeliefVariable b, String kind) {
        ObjectNode node = header(b);
        node.put("kind", kind);
        node.put("reference", Numbers.clean(Evidence.reference(b)));
        if (b.getSurvival() == null) {
            node.putNull("survivalMs");
        } else {
            node.put("survivalMs", Numbers.clean(Evidence.exactMillis(b.getSurvival())));
        }
        array("beliefs").add(node);
        return node;
    }

    // ------------------------------------------------------------------ actions

    @Override
    public ObjectNode caseReinforces(Reinforces r) {
        return evidence(r, "reinforces");
    }

    @Override
    public ObjectNode caseUndermines(Undermines u) {
        return evidence(u, "undermines");
    }

    private ObjectNode evidence(EvidenceAction a, String kind) {
        ObjectNode node = JSON.objectNode().put("kind", kind);
        node.put("belief", reference(a, a.getBelief()));
        node.put("strength", Evidence.strength(a.getStrength()).name());
        if (a.getSurvival() == null) {
            node.putNull("survivalMs");
        } else {
            node.put("survivalMs", Numbers.clean(Evidence.exactMillis(a.getSurvival())));
        }
        return node;
    }

    @Override
    public ObjectNode caseClears(Clears c) {
        return JSON.objectNode().put("kind", "clears").put("belief", reference(c, c.getBelief()));
    }

    @Override
    public ObjectNode caseSets(Sets s) {
        ObjectNode node = JSON.objectNode().put("kind", "sets").put("var", reference(s, s.getVariable()));
        node.set("value", expressions.expr(s.getValue()));
        return node;
    }

    @Override
    public ObjectNode caseTimerAction(TimerAction t) {
        String kind = switch (t.getKind()) {
            case STARTS -> "starts";
            case STOPS -> "stops";
            case RESUMES -> "resumes";
        };
        return JSON.objectNode().put("kind", kind).put("timer", reference(t, t.getTimer()));
    }

    private String reference(EObject from, EObject declaration) {
        String id = declarations.id(declaration);
        if (id == null) {
            errors.add(new GenerationError(from, "the action's target is not declared in this model or a file it "
                    + "imports", RoqmeRuntimeModel.REFERENCE));
            return "?";
        }
        return id;
    }

    // ------------------------------------------------------------------ types

    @Override
    public ObjectNode caseBooleanType(BooleanType t) {
        return type(t, "boolean");
    }

    @Override
    public ObjectNode caseEventType(EventType t) {
        return type(t, "eventtype");
    }

    @Override
    public ObjectNode caseNumericType(NumericType t) {
        ObjectNode node = bounded(t, "number");
        if (t.getUnit() != null) {
            node.put("unit", t.getUnit());
        }
        return node;
    }

    @Override
    public ObjectNode caseTimeType(TimeType t) {
        return bounded(t, "time");
    }

    @Override
    public ObjectNode caseEnumType(EnumType t) {
        ObjectNode node = type(t, "enum");
        ArrayNode literals = node.putArray("literals");
        for (EnumLiteral literal : t.getLiterals()) {
            literals.add(literal.getName());
        }
        return node;
    }

    @Override
    public ObjectNode caseTypeReference(TypeReference t) {
        return doSwitch(t.getType().getType());
    }

    private static ObjectNode bounded(BoundedType t, String kind) {
        ObjectNode node = type(t, kind);
        if (t.getLower() != null) {
            node.put("lower", Numbers.clean(t.getLower()));
        }
        if (t.getUpper() != null) {
            node.put("upper", Numbers.clean(t.getUpper()));
        }
        return node;
    }

    private static ObjectNode type(DataType t, String kind) {
        ObjectNode node = JSON.objectNode().put("kind", kind);
        if (t.getCardinality() > 0) {
            node.put("cardinality", t.getCardinality());
        }
        return node;
    }

    /** A declaration, action or type this writer has no case for: refused, never written half. */
    @Override
    public ObjectNode defaultCase(EObject e) {
        errors.add(new GenerationError(e, "the runtime model cannot represent a RoQME " + e.eClass().getName() + " yet",
                RoqmeRuntimeModel.ELEMENT));
        return JSON.objectNode();
    }
}
