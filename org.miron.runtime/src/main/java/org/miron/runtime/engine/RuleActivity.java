package org.miron.runtime.engine;

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
    final NativeModel m;
    /** The last evaluation's parameters by slot and decisions by varpoint ({@link DecisionExplainer} reads them). */
    final double[] param;
    final int[] assign;

    /**
     * One decision's rules and varpoints.
     *
     * @param holds per rule (priority order): its contexts are known and its condition holds
     * @param kept  per rule: not dropped for higher ones
     * @param asked per varpoint: something asks to change it
     */
    record Activity(boolean[] holds, boolean[] kept, boolean[] asked) {
    }

    RuleActivity(IoModel io) {
        m = new NativeModel(io);
        param = new double[m.paramNames.length];
        assign = new int[m.varpointCount];
    }

    /** Null when an input is missing (the backend then failed anyway). */
    Activity evaluate(Map<String, Object> params, Map<String, Integer> decisions, List<String> dropped) {
        if (m.readParams(params, param) != null) {
            return null;
        }
        boolean[] asked = new boolean[m.varpointCount];
        for (int v = 0; v < m.varpointCount; v++) {
            assign[v] = decisions.getOrDefault(m.decisionNames[v], 0);
            asked[v] = m.utilityMetric[v].length > 0 || overridden(v);
        }
        int rules = m.ruleNames.length;
        boolean[] holds = new boolean[rules];
        boolean[] kept = new boolean[rules];
        for (int r = 0; r < rules; r++) {
            for (int v : m.ruleConditionVars[r]) {
                asked[v] = true;
            }
            holds[r] = known(r) && m.pool.holds(m.ruleCondition[r], param, assign);
            kept[r] = !dropped.contains(m.ruleNames[r]);
        }
        for (NativeModel.Constraint k : m.constraints) {
            if (holds[k.rule()] && kept[k.rule()]) {
                for (int v : k.overrides()) {
                    asked[v] = true;
                }
            }
        }
        return new Activity(holds, kept, asked);
    }

    boolean overridden(int varpoint) {
        return param[m.inputSlot[varpoint]] == 1;
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
