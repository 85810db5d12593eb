package org.miron.runtime.roqme.expr;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import org.miron.runtime.roqme.expr.CompiledModel.Computed;
import org.miron.runtime.roqme.model.ModelException;

/** The computed slots (derived contexts, vars, windows) in dependency order; a cycle is refused. */
final class DependencyOrder {
    private final Map<Integer, Computed> computed;
    private final Map<Integer, String> at;
    private final Map<Integer, Integer> state = new HashMap<>(); // 1 visiting, 2 done
    private final List<Computed> out = new ArrayList<>();

    private DependencyOrder(Map<Integer, Computed> computed, Map<Integer, String> at) {
        this.computed = computed;
        this.at = at;
    }

    /** @param at the declaration of each slot, for the message naming a cycle */
    static List<Computed> of(Map<Integer, Computed> computed, Map<Integer, String> at) throws ModelException {
        DependencyOrder o = new DependencyOrder(computed, at);
        for (Integer slot : new TreeSet<>(computed.keySet())) {
            o.visit(slot);
        }
        return o.out;
    }

    private void visit(int slot) throws ModelException {
        Computed c = computed.get(slot);
        if (c == null || Integer.valueOf(2).equals(state.get(slot))) {
            return;
        }
        if (Integer.valueOf(1).equals(state.get(slot))) {
            throw new ModelException(at.get(slot), "roqme-cycle", "a derived context or var depends on itself");
        }
        state.put(slot, 1);
        for (int d : c.deps()) {
            visit(d);
        }
        state.put(slot, 2);
        out.add(c);
    }
}
