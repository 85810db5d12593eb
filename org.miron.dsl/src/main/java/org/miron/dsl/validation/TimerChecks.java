package org.miron.dsl.validation;

import static org.miron.dsl.validation.RoqmeIssueCodes.*;
import static org.miron.dsl.validation.Texts.text;

import java.util.List;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.EcoreUtil2;
import org.eclipse.xtext.nodemodel.INode;
import org.eclipse.xtext.nodemodel.util.NodeModelUtils;
import org.eclipse.xtext.validation.Check;
import org.miron.dsl.roqme.Expression;
import org.miron.dsl.roqme.FunctionCall;
import org.miron.dsl.roqme.RoqmePackage;
import org.miron.dsl.roqme.StringValue;
import org.miron.dsl.roqme.TimeValue;
import org.miron.dsl.roqme.Timer;
import org.miron.dsl.roqme.TimerAction;
import org.miron.dsl.roqme.TimerActionKind;
import org.miron.dsl.roqme.UnaryExpression;
import org.miron.dsl.roqme.UnaryOperator;
import org.miron.dsl.util.CronSchedule;
import org.miron.dsl.util.ExprType;
import org.miron.dsl.util.Types;

/**
 * Timers and schedules. A timer is defined by its period, a positive time, or by a calendar
 * schedule("cron"); it then fires as an event (its type in expressions is event, see Types). The
 * cron string of every schedule(...) must have five valid fields.
 */
public class TimerChecks extends CheckSet {

    private static final RoqmePackage R = RoqmePackage.eINSTANCE;

    @Check
    public void checkDefinition(Timer timer) {
        Expression def = timer.getDefinition();
        if (def == null) {
            return;
        }
        if (isSchedule(def)) {
            if (timer.getOffset() != null) {
                warning("the offset of timer '" + timer.getName() + "' has no effect: a schedule fires at the times "
                        + "of its calendar", timer, R.getTimer_Offset(), SCHEDULE_OFFSET);
            }
            return;
        }
        ExprType type = Types.typeOf(def);
        if (type.kind != ExprType.Kind.TIME && !type.isUnknown()) {
            String hint = type.isEventLike() ? "; to time an event, start the timer from an observation: "
                    + "'observation o : " + text(def) + " starts " + timer.getName() + "'" : "";
            error("timer '" + timer.getName() + "' needs a period (a time such as 10 minutes) or schedule(\"cron\"), "
                    + "not " + type + hint, timer, R.getTimer_Definition(), TIMER_DEFINITION);
            return;
        }
        Double period = constantPeriod(def);
        if (period != null && period <= 0) {
            error("the period of timer '" + timer.getName() + "' must be positive, not " + text(def), timer,
                    R.getTimer_Definition(), PERIOD_NOT_POSITIVE);
        }
    }

    /** A paused timer fires only once an observation starts or resumes it. */
    @Check
    public void checkPausedIsStarted(Timer timer) {
        if (!timer.isPaused()) {
            return;
        }
        EObject root = EcoreUtil.getRootContainer(timer);
        for (TimerAction action : EcoreUtil2.getAllContentsOfType(root, TimerAction.class)) {
            if (action.getTimer() == timer && action.getKind() != TimerActionKind.STOPS) {
                return;
            }
        }
        warning("timer '" + timer.getName() + "' is paused and no observation of this file starts or resumes it, "
                + "so it never fires here", timer, R.getVariable_Name(), PAUSED_TIMER_NEVER_STARTED);
    }

    @Check
    public void checkSchedule(FunctionCall call) {
        if (!"schedule".equals(call.getFunction()) || call.getArgs().size() != 1) {
            return; // the arity is checked with the other functions
        }
        Expression arg = call.getArgs().get(0);
        if (!(arg instanceof StringValue)) {
            error("schedule needs a cron string such as \"0 8 * * *\", not " + text(arg), call,
                    R.getFunctionCall_Args(), 0, INVALID_SCHEDULE);
            return;
        }
        String cron = ((StringValue) arg).getValue();
        CronSchedule.Problem problem = cron == null ? null : CronSchedule.check(cron);
        if (problem == null) {
            return;
        }
        String message = "invalid schedule \"" + cron + "\": " + problem.message;
        List<INode> nodes = NodeModelUtils.findNodesForFeature(arg, R.getStringValue_Value());
        INode node = nodes.isEmpty() ? null : nodes.get(0);
        String raw = node == null ? "" : node.getText();
        if (raw.length() >= 2 && raw.substring(1, raw.length() - 1).equals(cron)) {
            // no escape sequences: offsets in the value are offsets in the source, after the quote
            getMessageAcceptor().acceptError(message, arg, node.getOffset() + 1 + problem.offset, problem.length,
                    INVALID_SCHEDULE);
        } else {
            error(message, arg, R.getStringValue_Value(), INVALID_SCHEDULE);
        }
    }

    private static boolean isSchedule(Expression e) {
        return e instanceof FunctionCall && "schedule".equals(((FunctionCall) e).getFunction());
    }

    /** The period in its own unit when written as a literal time, or its negation; otherwise null. */
    private static Double constantPeriod(Expression e) {
        if (e instanceof TimeValue) {
            return ((TimeValue) e).getValue();
        }
        if (e instanceof UnaryExpression && ((UnaryExpression) e).getOperator() == UnaryOperator.MINUS) {
            Double inner = constantPeriod(((UnaryExpression) e).getTerm());
            return inner == null ? null : -inner;
        }
        return null;
    }
}
