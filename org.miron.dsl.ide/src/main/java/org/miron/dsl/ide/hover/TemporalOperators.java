package org.miron.dsl.ide.hover;

import org.miron.dsl.miron.Requirement;
import org.miron.dsl.miron.TemporalExpression;
import org.miron.dsl.util.Evidence;
import org.miron.dsl.util.Formulas;

/** What a requirement and its temporal operators mean (docs/requirements.md), for hovers: one line each. */
final class TemporalOperators {
    private TemporalOperators() {
    }

    static String describe(TemporalExpression t) {
        String within = t.getBound() == null ? "" : " within " + Evidence.describe(Evidence.exactMillis(t.getBound()));
        return switch (t.getOperator()) {
            case ALWAYS -> t.getBound() == null ? "always φ: φ holds at every instant of the run"
                    : "always" + within + " φ: φ holds at every instant of the next" + within.substring(" within".length());
            case NEVER -> t.getBound() == null ? "never φ: φ holds at no instant of the run (always not φ)"
                    : "never" + within + " φ: φ holds at no instant of the next" + within.substring(" within".length());
            case EVENTUALLY -> t.getBound() == null ? "eventually φ: φ holds at some instant of the run"
                    : "eventually" + within + " φ: φ holds at some instant before" + within.substring(" within".length())
                            + " have passed";
        };
    }

    /** "**requirement r**: `formula`" and whether every run must satisfy it or how likely one must. */
    static String describe(Requirement r) {
        return "**requirement " + r.getName() + "**: `" + Formulas.text(r.getFormula()) + "`\n\n"
                + (r.getProbability() == null ? "every run must satisfy it"
                        : "a run must satisfy it with probability at least " + Evidence.number(r.getProbability()));
    }
}
