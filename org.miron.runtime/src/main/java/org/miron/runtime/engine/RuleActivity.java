package org.miron.runtime.engine;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * Which rules a decision applied and which varpoints something asked to change, evaluated on the
 * io.json's decision section whatever backend decided: a varpoint is asked when it has impacts,
 * is overridden by hand, is constrained by a consequence of a kept rule whose condition holds, or is
 * read by a rule's condition (changing it could change which rules apply). The engine sends nothing
 * for a varpoint nobody asks: it keeps its applied (or initial) value.
 */
final class RuleActivity {
    private final NativeModel m;
    private final double[] param;
    private final int[] assign;

    /** The decisions of one solve, in the model's terms. */
    record Activity(List<String> applied, boolean[] asked) {
    }

    RuleActivity(IoModel io) {
        m = new NativeModel(io);
        param = new double[m.paramNames.length];
        assign = new int[m.varpointCount];
    }

    /** Null when an input is missing (the backend then failed anyway). */
    Activity evaluate(Map<String, Object> params, Map<String, Integer> decisions, List<String> dropped) {
        for (int s = 0; s < param.length; s++) {
            Object o = params.get(m.paramNames[s]);
            if (o instanceof Boolean b) {
                param[s] = b ? 1 : 0;
            } else if (o instanceof Number x) {
                param[s] = x.doubleValue();
            } else {
                return null;
            }
        }
        boolean[] asked = new boolean[m.varpointCount];
        for (int v = 0; v < m.varpointCount; v++) {
            assign[v] = decisions.getOrDefault(m.decisionNames[v], 0);
            asked[v] = m.utilityMetric[v].length > 0 || param[m.inputSlot[v]] == 1;
        }
        List<String> applied = new ArrayList<>();
        boolean[] holds = new boolean[m.ruleNames.length];
        for (int r = 0; r < m.ruleNames.length; r++) {
            for (int v : m.ruleConditionVars[r]) {
                asked[v] = true;
            }
            holds[r] = known(r) && m.pool.holds(m.ruleCondition[r], param, assign);
            if (holds[r]) {
                applied.add(m.ruleNames[r]);
            }
        }
        for (NativeModel.Constraint k : m.constraints) {
            if (holds[k.rule()] && !dropped.contains(m.ruleNames[k.rule()])) {
                for (int v : k.overrides()) {
                    asked[v] = true;
                }
            }
        }
        return new Activity(applied, asked);
    }

    private boolean known(int rule) {
        for (int slot : m.ruleKnown[rule]) {
            if (param[slot] != 1) {
                return false;
            }
        }
        return true;
    }
}
