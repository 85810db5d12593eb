package org.miron.runtime.requirement;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.BitSet;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Consumer;
import org.miron.runtime.engine.ExpressionPool;
import org.miron.runtime.requirement.RequirementModel.Requirement;
import org.miron.runtime.requirement.RequirementModel.Signal;

/**
 * Every requirement of a model, monitored online over one run (docs/requirements.md, "Semantics").
 * Fed with what the robot perceives, the provider estimates and the engine applies, each at the
 * time it happens (milliseconds since the start of the run, not decreasing); the values of one
 * instant are taken together, whatever their order, once time moves on. Used alike by the
 * simulator (a virtual clock) and on the bus (the wall clock, {@link #advance} on a timer so that a
 * deadline passes without a message). Not thread-safe: one feeder.
 */
public final class RequirementMonitors {
    private final RequirementModel model;
    private final Signals signals;
    private final ExpressionPool pool;
    private final List<Atom> atoms = new ArrayList<>();
    private final List<RequirementMonitor> monitors = new ArrayList<>();
    private final Map<String, List<Integer>> contexts = new HashMap<>();
    private final Map<String, List<Integer>> properties = new HashMap<>();
    private final Map<String, List<Integer>> varpoints = new HashMap<>();
    private Consumer<RequirementEvent> listener = e -> {
    };
    private long now;
    private long rejected;
    private List<RequirementResult> results;

    /** Compiles every formula; a formula the monitors cannot run is an IllegalArgumentException naming it. */
    public RequirementMonitors(RequirementModel model) {
        this.model = model;
        this.signals = new Signals(model.signals());
        Map<String, Integer> params = new HashMap<>();
        Map<String, Integer> vps = new HashMap<>();
        List<double[]> tables = new ArrayList<>();
        for (int i = 0; i < signals.defs.length; i++) {
            Signal s = signals.defs[i];
            switch (s.kind()) {
                case "context" -> contexts.computeIfAbsent(s.source(), k -> new ArrayList<>()).add(i);
                case "property" -> properties.computeIfAbsent(s.source(), k -> new ArrayList<>()).add(i);
                default -> varpoints.computeIfAbsent(s.source(), k -> new ArrayList<>()).add(i);
            }
            if (s.isVarpoint()) {
                vps.put(s.source(), signals.vpSlot[i]);
                double[] t = new double[s.literals().size()];
                for (int k = 0; k < t.length; k++) {
                    JsonNode x = s.literals().get(k);
                    t[k] = x.isNumber() ? x.asDouble() : x.isBoolean() ? (x.asBoolean() ? 1 : 0) : k;
                }
                tables.add(t);
            } else {
                params.put(s.param(), i);
            }
        }
        pool = new ExpressionPool(params, vps, tables.toArray(new double[0][]));
        Map<String, Integer> signalOfVarpoint = new HashMap<>();
        for (int i = 0; i < signals.defs.length; i++) {
            if (signals.defs[i].isVarpoint()) {
                signalOfVarpoint.put(signals.defs[i].source(), i);
            }
        }
        for (Requirement r : model.requirements()) {
            try {
                List<Atom> own = new ArrayList<>();
                JsonNode f = r.formula();
                String op = f.path("op").asText();
                FormulaNode body = null;
                long until = Eventually.UNBOUNDED;
                if (op.equals("always") || op.equals("never")) {
                    FormulaNode arg = compile(only(f), own, params, signalOfVarpoint);
                    body = op.equals("always") ? arg : new Combination(Combination.Op.NOT, arg, null);
                    until = within(f);
                }
                FormulaNode root = body != null ? null : compile(f, own, params, signalOfVarpoint);
                Set<Integer> reads = new LinkedHashSet<>();
                for (String name : r.reads()) {
                    reads.add(indexOf(name));
                }
                own.forEach(a -> {
                    for (int s : a.reads) {
                        reads.add(s);
                    }
                });
                RequirementMonitor m = new RequirementMonitor(r, reads.stream().mapToInt(Integer::intValue).toArray(), root,
                        body, until);
                monitors.add(m);
                own.forEach(a -> a.owner = m);
                atoms.addAll(own);
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException("requirement " + r.name() + ": " + e.getMessage(), e);
            }
        }
    }

    private int indexOf(String name) {
        for (int i = 0; i < signals.defs.length; i++) {
            if (signals.defs[i].name().equals(name)) {
                return i;
            }
        }
        throw new IllegalArgumentException("reads unknown signal '" + name + "'");
    }

    private FormulaNode compile(JsonNode f, List<Atom> own, Map<String, Integer> params, Map<String, Integer> vps) {
        if (f.has("state")) {
            BitSet unused = new BitSet();
            int node = pool.compile(f.get("state"), unused);
            Set<Integer> reads = new LinkedHashSet<>();
            collectReads(f.get("state"), params, vps, reads);
            Atom a = new Atom(node, reads.stream().mapToInt(Integer::intValue).toArray());
            for (int s : a.reads) {
                signals.readers.get(s).add(a);
            }
            own.add(a);
            return a;
        }
        String op = f.path("op").asText();
        JsonNode args = f.path("args");
        return switch (op) {
            case "not" -> new Combination(Combination.Op.NOT, compile(only(f), own, params, vps), null);
            case "and", "or", "implies" -> {
                if (args.size() != 2) {
                    throw new IllegalArgumentException("'" + op + "' needs 2 arguments, has " + args.size());
                }
                yield new Combination(Combination.Op.valueOf(op.toUpperCase(java.util.Locale.ROOT)),
                        compile(args.get(0), own, params, vps), compile(args.get(1), own, params, vps));
            }
            case "eventually" -> new Eventually(compile(only(f), own, params, vps), within(f));
            case "always" -> not(new Eventually(not(compile(only(f), own, params, vps)), within(f)));
            case "never" -> not(new Eventually(compile(only(f), own, params, vps), within(f)));
            default -> throw new IllegalArgumentException("unknown formula operator '" + op + "'");
        };
    }

    private static FormulaNode not(FormulaNode n) {
        return new Combination(Combination.Op.NOT, n, null);
    }

    private static JsonNode only(JsonNode f) {
        JsonNode args = f.path("args");
        if (args.size() != 1) {
            throw new IllegalArgumentException("'" + f.path("op").asText() + "' needs 1 argument, has " + args.size());
        }
        return args.get(0);
    }

    private static long within(JsonNode f) {
        JsonNode w = f.path("within");
        if (w.isMissingNode() || w.isNull()) {
            return Eventually.UNBOUNDED;
        }
        if (!w.canConvertToLong() || w.asLong() < 0) {
            throw new IllegalArgumentException("bound " + w + " is not a non-negative number of milliseconds");
        }
        return w.asLong();
    }

    private static void collectReads(JsonNode e, Map<String, Integer> params, Map<String, Integer> vps, Set<Integer> out) {
        if (e.has("param")) {
            out.add(params.get(e.get("param").asText()));
        } else if (e.has("index") || e.has("value")) {
            out.add(vps.get(e.path(e.has("index") ? "index" : "value").asText()));
        }
        e.path("args").forEach(a -> collectReads(a, params, vps, out));
    }

    public RequirementModel model() {
        return model;
    }

    /** Called with every violation and every {@code met}, in the order they are known. */
    public RequirementMonitors onEvent(Consumer<RequirementEvent> listener) {
        this.listener = listener;
        return this;
    }

    /** The RoQME contexts the requirements read (by their RoQME names). */
    public Set<String> contexts() {
        return contexts.keySet();
    }

    public Set<String> properties() {
        return properties.keySet();
    }

    /** Values that could not be taken (an unknown literal, a value no varpoint has): counted, not fatal. */
    public long rejected() {
        return rejected;
    }

    /** A context's value: a Number, a Boolean, an enum literal (String) or a JSON value; an event: anything. */
    public boolean context(long t, String name, Object value) {
        List<Integer> sigs = contexts.get(name);
        if (sigs == null) {
            return true; // not read by any requirement
        }
        at(t);
        boolean ok = true;
        for (int s : sigs) {
            double v = decode(signals.defs[s], value instanceof JsonNode j ? j : org.miron.runtime.Json.MAPPER.valueToTree(value));
            if (Double.isNaN(v)) {
                ok = false;
                rejected++;
            } else {
                signals.set(s, v);
            }
        }
        return ok;
    }

    public void estimate(long t, String property, double value) {
        List<Integer> sigs = properties.get(property);
        if (sigs == null) {
            return;
        }
        at(t);
        for (int s : sigs) {
            signals.set(s, value);
        }
    }

    /** The value a varpoint was set to (an enum literal, a number, a Boolean, as io.json lists them). */
    public boolean varpoint(long t, String name, JsonNode value) {
        List<Integer> sigs = varpoints.get(name);
        if (sigs == null) {
            return true;
        }
        at(t);
        boolean ok = true;
        for (int s : sigs) {
            int index = indexOf(signals.defs[s].literals(), value);
            if (index < 0) {
                ok = false;
                rejected++;
            } else {
                signals.set(s, index);
            }
        }
        return ok;
    }

    private static int indexOf(List<JsonNode> values, JsonNode v) {
        for (int i = 0; i < values.size(); i++) {
            JsonNode x = values.get(i);
            if (x.isNumber() && v.isNumber() ? Math.abs(x.asDouble() - v.asDouble()) < 1e-9 : x.equals(v)
                    || (x.isTextual() && x.asText().equals(v.asText()))) {
                return i;
            }
        }
        return -1;
    }

    private static double decode(Signal s, JsonNode v) {
        return switch (s.type()) {
            case "event" -> 1;
            case "boolean" -> v.isBoolean() ? (v.asBoolean() ? 1 : 0) : v.isNumber() ? (v.asDouble() != 0 ? 1 : 0) : Double.NaN;
            case "enum" -> {
                for (int i = 0; i < s.literals().size(); i++) {
                    if (s.literals().get(i).asText().equals(v.asText())) {
                        yield i;
                    }
                }
                yield Double.NaN;
            }
            default -> v.isNumber() ? v.asDouble() : Double.NaN;
        };
    }

    /** Time moves on to {@code t}: what held since the last instant held until then. */
    public void advance(long t) {
        at(t);
    }

    private void at(long t) {
        if (results != null) {
            throw new IllegalStateException("the run is over");
        }
        if (t > now) {
            close(t);
        }
    }

    /** The instant {@code now} is over: its values hold on {@code [now, next)}; the monitors look. */
    private void close(long next) {
        signals.record(now);
        evaluate();
        boolean pulse = signals.pulsed;
        long until = pulse ? now + 1 : next;
        extend(until);
        if (pulse) {
            signals.endPulses();
            signals.record(now + 1);
            evaluate();
            if (until < next) {
                extend(next);
            }
        }
        now = next;
        signals.at(now);
        long keep = Long.MAX_VALUE;
        for (RequirementMonitor m : monitors) {
            m.update(now, signals, listener);
            keep = Math.min(keep, m.pendingFrom());
        }
        signals.forgetBefore(Math.min(keep, now));
    }

    private void evaluate() {
        for (Atom a : atoms) {
            if (a.dirty) {
                a.dirty = false;
                a.value = truth(a);
            }
        }
    }

    private void extend(long until) {
        for (Atom a : atoms) {
            if (!a.owner.finished()) {
                a.out.append(a.out.horizon(), until, a.value);
            }
        }
    }

    private Truth truth(Atom a) {
        for (int s : a.reads) {
            if (Double.isNaN(signals.value[s])) {
                return Truth.OPEN;
            }
        }
        return Truth.of(pool.holds(a.node, signals.value, signals.assign));
    }

    /** How many instants of the past the monitors still remember (bounded by the largest window). */
    public int remembered() {
        return signals.remembered();
    }

    /**
     * The run ended at {@code end} (its last instant, included): every window still open is
     * decided, OPEN where it reaches past the end. Returns each requirement's result, in order.
     */
    public List<RequirementResult> finish(long end) {
        if (results != null) {
            return results;
        }
        at(end);
        signals.record(now);
        evaluate();
        List<RequirementResult> out = new ArrayList<>();
        for (RequirementMonitor m : monitors) {
            out.add(m.finish(end, signals, listener)); // its atoms take their values at the end up to end + 1
        }
        results = List.copyOf(out);
        return results;
    }
}
