package org.miron.runtime.roqme.expr;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import org.miron.runtime.roqme.expr.CompiledModel.CompiledAction;
import org.miron.runtime.roqme.expr.CompiledModel.CompiledBelief;
import org.miron.runtime.roqme.expr.CompiledModel.CompiledObservation;
import org.miron.runtime.roqme.expr.CompiledModel.Computed;
import org.miron.runtime.roqme.expr.Symbol.Kind;
import org.miron.runtime.roqme.model.ModelException;
import org.miron.runtime.roqme.model.RoqmeModel;
import org.miron.runtime.roqme.model.RoqmeModel.Variable;
import org.miron.runtime.roqme.reasoner.Strength;

/**
 * Checks a runtime model's references and compiles its expressions. Anything the provider cannot
 * run is a {@link ModelException} at the declaration's {@code at}, so a model is refused at start,
 * never half-running.
 */
public final class Compiler {
    static final long DEFAULT_SURVIVAL_MS = 5 * 60_000;
    private final RoqmeModel model;
    private final Map<String, Symbol> symbols = new LinkedHashMap<>();
    private final List<Window> windows = new ArrayList<>();
    private final List<RoqmeModel.Timer> timers = new ArrayList<>();
    private final Map<Integer, Computed> computedBySlot = new HashMap<>();
    private final Map<Integer, String> atBySlot = new HashMap<>();
    private int slots;
    private String at; // declaration being compiled, for messages
    private Integer selfBelief; // slot of the property whose expression is compiled

    private Compiler(RoqmeModel model) {
        this.model = model;
    }

    /** Compiles {@code model}; {@code params} overrides param defaults by id or name (text values). */
    public static CompiledModel compile(RoqmeModel model, Map<String, String> params) throws ModelException {
        return new Compiler(model).run(params);
    }

    private CompiledModel run(Map<String, String> params) throws ModelException {
        Map<String, String> asGiven = Map.copyOf(params);
        declare(model.contexts(), Kind.CONTEXT);
        declare(model.params(), Kind.PARAM);
        declare(model.vars(), Kind.VAR);
        for (RoqmeModel.Timer t : model.timers()) {
            at = t.at();
            if ((t.periodMs() == null) == (t.schedule() == null)) {
                throw error("roqme-timer", "timer " + t.id() + " needs exactly one of periodMs and schedule");
            }
            if (t.periodMs() != null && t.periodMs() <= 0) {
                throw error("roqme-timer", "timer " + t.id() + " has a non-positive period " + t.periodMs() + " ms");
            }
            if (t.schedule() != null) {
                try {
                    Cron.parse(t.schedule());
                } catch (IllegalArgumentException e) {
                    throw error("roqme-cron", "timer " + t.id() + ": " + e.getMessage());
                }
            }
            put(new Symbol(t.id(), Kind.TIMER, slots++, null, t.at()));
            timers.add(t);
        }
        for (RoqmeModel.Belief b : model.beliefs()) {
            at = b.at();
            if (b.ref() < 0 || b.ref() > 1) {
                throw error("roqme-reference", "reference " + b.ref() + " of " + b.id() + " is outside [0,1]");
            }
            put(new Symbol(b.id(), Kind.BELIEF, slots++, b.type(), b.at()));
        }
        Map<Integer, Object> initial = new HashMap<>();
        for (Variable v : model.params()) {
            at = v.at();
            Symbol s = symbols.get(v.id());
            String given = params.containsKey(v.id()) ? params.remove(v.id()) : params.remove(v.name());
            Object value = given != null ? Literals.parse(given, v.type(), v.id())
                    : v.defaultValue() == null || v.defaultValue().isNull() ? null : Literals.of(v.defaultValue());
            if (given == null && value == null) {
                throw error("roqme-param", "param " + v.id() + " has no default: give it with --param " + v.name() + "=VALUE");
            }
            if (given != null && value == null) {
                throw error("roqme-param", "--param " + v.id() + "=" + given + " is not a " + Literals.describe(v.type()));
            }
            initial.put(s.slot(), value);
        }
        if (!params.isEmpty()) {
            throw new ModelException(model.source() == null ? model.model() : model.source(), "roqme-param",
                    "--param " + params.keySet().iterator().next() + ": the model declares no such param");
        }
        for (Variable v : model.contexts()) {
            if (v.derived() != null && !v.derived().isNull()) {
                computed(v, v.derived());
            }
        }
        for (Variable v : model.vars()) {
            if (v.init() != null && !v.init().isNull()) {
                computed(v, v.init());
            } else {
                computedBySlot.put(symbols.get(v.id()).slot(), new Computed(symbols.get(v.id()).slot(), null, null, new int[0]));
            }
        }
        List<CompiledBelief> beliefs = new ArrayList<>();
        for (RoqmeModel.Belief b : model.beliefs()) {
            at = b.at();
            int slot = symbols.get(b.id()).slot();
            ValueNode e = null;
            if (b.expr() != null && !b.expr().isNull()) {
                selfBelief = slot;
                e = value(b.expr(), new TreeSet<>());
                selfBelief = null;
            }
            beliefs.add(new CompiledBelief(beliefs.size(), slot, b, e));
        }
        List<CompiledObservation> observations = new ArrayList<>();
        for (RoqmeModel.Observation o : model.observations()) {
            at = o.at();
            if (o.pattern() == null || o.pattern().isNull()) {
                throw error("roqme-pattern", "observation " + o.id() + " has no pattern");
            }
            TreeSet<Integer> deps = new TreeSet<>();
            EventNode p = event(o.pattern(), deps);
            List<CompiledAction> actions = new ArrayList<>();
            for (RoqmeModel.Action a : o.actions()) {
                actions.add(action(o, a));
            }
            observations.add(new CompiledObservation(observations.size(), o.id(), o, p, ints(deps), actions));
        }
        return new CompiledModel(model, slots, Map.copyOf(symbols), DependencyOrder.of(computedBySlot, atBySlot), List.copyOf(timers), List.copyOf(windows), observations,
                beliefs, initial, asGiven, new java.util.concurrent.atomic.AtomicBoolean());
    }

    private void declare(List<Variable> vars, Kind kind) throws ModelException {
        for (Variable v : vars) {
            at = v.at();
            if (v.type() == null || v.type().kind() == null) {
                throw error("roqme-type", v.id() + " has no type");
            }
            if (!List.of("number", "boolean", "eventtype", "time", "enum").contains(v.type().kind())) {
                throw error("roqme-type", v.id() + " has an unsupported type " + v.type().kind());
            }
            put(new Symbol(v.id(), kind, slots++, v.type(), v.at()));
        }
    }

    private void put(Symbol s) throws ModelException {
        if (s.id() == null) {
            throw error("roqme-id", "a declaration has no id");
        }
        if (symbols.put(s.id(), s) != null) {
            throw error("roqme-id", "duplicate id " + s.id());
        }
        atBySlot.put(s.slot(), s.at());
    }

    private void computed(Variable v, JsonNode expr) throws ModelException {
        at = v.at();
        TreeSet<Integer> deps = new TreeSet<>();
        ValueNode e = value(expr, deps);
        int slot = symbols.get(v.id()).slot();
        computedBySlot.put(slot, new Computed(slot, e, null, ints(deps)));
    }

    private CompiledAction action(RoqmeModel.Observation o, RoqmeModel.Action a) throws ModelException {
        String kind = a.kind() == null ? "" : a.kind();
        switch (kind) {
            case "reinforces", "undermines", "clears" -> {
                Symbol b = lookup(a.belief(), "belief");
                if (b.kind() != Kind.BELIEF) {
                    throw error("roqme-action", o.id() + ": " + a.belief() + " is not a property or beliefvar");
                }
                if (kind.equals("clears")) {
                    return new CompiledAction(CompiledAction.Kind.of(kind), b.slot(), 1, 0, null);
                }
                RoqmeModel.Belief decl = model.beliefs().stream().filter(x -> x.id().equals(b.id())).findFirst().orElseThrow();
                long survival = a.survivalMs() != null ? a.survivalMs()
                        : decl.survivalMs() != null ? decl.survivalMs() : DEFAULT_SURVIVAL_MS;
                if (survival <= 0) {
                    throw error("roqme-survival", o.id() + ": non-positive survival " + survival + " ms");
                }
                double r;
                try {
                    r = Strength.ratio(kind, a.strength());
                } catch (IllegalArgumentException e) {
                    throw error("roqme-action", o.id() + ": " + e.getMessage());
                }
                return new CompiledAction(CompiledAction.Kind.of(kind), b.slot(), r, survival, null);
            }
            case "sets" -> {
                Symbol v = lookup(a.var(), "var");
                if (v.kind() != Kind.VAR) {
                    throw error("roqme-action", o.id() + ": sets " + a.var() + ", which is not a var");
                }
                if (a.value() == null) {
                    throw error("roqme-action", o.id() + ": sets " + a.var() + " without a value");
                }
                return new CompiledAction(CompiledAction.Kind.of(kind), v.slot(), 1, 0, value(a.value(), new TreeSet<>()));
            }
            case "starts", "stops", "resumes" -> {
                Symbol t = lookup(a.timer(), "timer");
                if (t.kind() != Kind.TIMER) {
                    throw error("roqme-action", o.id() + ": " + kind + " " + a.timer() + ", which is not a timer");
                }
                return new CompiledAction(CompiledAction.Kind.of(kind), t.slot(), 1, 0, null);
            }
            default -> throw error("roqme-action", o.id() + ": unsupported action kind '" + kind + "'");
        }
    }

    private Symbol lookup(String id, String what) throws ModelException {
        Symbol s = id == null ? null : symbols.get(id);
        if (s == null) {
            throw error("roqme-ref", "unknown " + what + " " + id);
        }
        return s;
    }

    // ---- patterns

    private EventNode event(JsonNode e, TreeSet<Integer> deps) throws ModelException {
        String op = e.path("op").asText(null);
        if (op != null) {
            switch (op) {
                case "and" -> {
                    JsonNode l = e.get("left");
                    JsonNode r = e.get("right");
                    if ("not".equals(r.path("op").asText())) {
                        return Events.andNot(event(l, deps), event(r.get("arg"), deps));
                    }
                    if ("not".equals(l.path("op").asText())) {
                        return Events.andNot(event(r, deps), event(l.get("arg"), deps));
                    }
                    return Events.and(event(l, deps), event(r, deps));
                }
                case "or" -> {
                    return Events.or(event(e.get("left"), deps), event(e.get("right"), deps));
                }
                case "->" -> {
                    return Events.followedBy(event(e.get("left"), deps), event(e.get("right"), deps));
                }
                case "once" -> {
                    return Events.once(event(e.get("arg"), deps));
                }
                case "while" -> {
                    return Events.whileTrue(event(e.get("arg"), deps), value(e.get("cond"), deps));
                }
                case "repeat" -> {
                    int n = e.path("times").asInt(0);
                    if (n < 1) {
                        throw error("roqme-pattern", "repeat needs a positive count, got " + e.path("times"));
                    }
                    return Events.repeat(event(e.get("arg"), deps), n);
                }
                case "range" -> {
                    int a = e.path("min").asInt(0);
                    int b = e.path("max").asInt(0);
                    if (a < 1 || b < a) {
                        throw error("roqme-pattern", "range(" + a + ", " + b + ") needs 1 <= min <= max");
                    }
                    return Events.range(event(e.get("arg"), deps), a, b);
                }
                case "not" -> {
                    if (!"boolean".equals(typeOf(e.get("arg")))) {
                        throw error("roqme-pattern", "'not' of an event is only meaningful as 'A and not B'");
                    }
                    return implicit(Map.entry("!", e.get("arg")), deps);
                }
                default -> {
                }
            }
        }
        if (e.has("call") && e.get("call").asText().equals("schedule")) {
            return schedule(e, deps);
        }
        if (e.has("call") && List.of("eventWhen", "update").contains(e.get("call").asText())) {
            JsonNode arg = e.path("args").path(0);
            if (arg.isMissingNode()) {
                throw error("roqme-pattern", e.get("call").asText() + " needs an argument");
            }
            return e.get("call").asText().equals("eventWhen") ? whenTrue(arg, deps) : update(arg, deps);
        }
        String type = typeOf(e);
        if ("event".equals(type)) {
            if (e.has("ref")) {
                return update(e, deps);
            }
            throw error("roqme-pattern", "unsupported event expression " + e);
        }
        return "boolean".equals(type) ? whenTrue(e, deps) : update(e, deps);
    }

    /** {@code schedule("cron")} in a pattern: an event at the cron times, as an unnamed timer. */
    private EventNode schedule(JsonNode e, TreeSet<Integer> deps) throws ModelException {
        JsonNode arg = e.path("args").path(0);
        if (!arg.has("string")) {
            throw error("roqme-cron", "schedule(...) needs a cron string literal");
        }
        String cron = arg.get("string").asText();
        try {
            Cron.parse(cron);
        } catch (IllegalArgumentException x) {
            throw error("roqme-cron", "schedule(\"" + cron + "\"): " + x.getMessage());
        }
        String id = "schedule(\"" + cron + "\")#" + timers.size();
        RoqmeModel.Timer t = new RoqmeModel.Timer(id, id, null, at, null, cron, 0, false, false);
        Symbol s = new Symbol(id, Kind.TIMER, slots++, null, at);
        symbols.put(id, s);
        timers.add(t);
        deps.add(s.slot());
        return Events.source(s.slot(), false);
    }

    private EventNode implicit(Map.Entry<String, JsonNode> notOf, TreeSet<Integer> deps) throws ModelException {
        TreeSet<Integer> own = new TreeSet<>();
        ValueNode v = Values.not(value(notOf.getValue(), own));
        deps.addAll(own);
        return Events.change(v, ints(own), true);
    }

    private EventNode whenTrue(JsonNode e, TreeSet<Integer> deps) throws ModelException {
        if (e.has("ref") && symbols.containsKey(e.get("ref").asText()) && symbols.get(e.get("ref").asText()).isEvent()) {
            return update(e, deps); // eventWhen of an event is the event
        }
        TreeSet<Integer> own = new TreeSet<>();
        ValueNode v = value(e, own);
        deps.addAll(own);
        return Events.change(v, ints(own), true);
    }

    private EventNode update(JsonNode e, TreeSet<Integer> deps) throws ModelException {
        if (e.has("ref")) {
            Symbol s = lookup(e.get("ref").asText(), "name");
            deps.add(s.slot());
            return Events.source(s.slot(), !s.isEvent());
        }
        TreeSet<Integer> own = new TreeSet<>();
        ValueNode v = value(e, own);
        deps.addAll(own);
        return Events.change(v, ints(own), false);
    }

    // ---- values

    ValueNode value(JsonNode e, TreeSet<Integer> deps) throws ModelException {
        if (e == null || !e.isObject()) {
            throw error("roqme-expr", "an expression must be a JSON object, got " + e);
        }
        if (Literals.isLiteral(e)) {
            if (e.has("sequence")) {
                List<ValueNode> items = new ArrayList<>();
                for (JsonNode i : e.get("sequence")) {
                    items.add(value(i, deps));
                }
                return s -> {
                    List<Object> l = new ArrayList<>(items.size());
                    for (ValueNode n : items) {
                        l.add(n.eval(s));
                    }
                    return l;
                };
            }
            return Values.constant(Literals.of(e));
        }
        if (e.has("ref")) {
            Symbol s = lookup(e.get("ref").asText(), "name");
            if (s.kind() == Kind.TIMER) {
                throw error("roqme-expr", "timer " + s.id() + " is an event, not a value");
            }
            deps.add(s.slot());
            return Values.ref(s.slot());
        }
        if (e.has("belief")) {
            int slot;
            if (e.get("belief").isNull()) {
                if (selfBelief == null) {
                    throw error("roqme-expr", "bare 'belief' outside a property's expression");
                }
                slot = selfBelief;
            } else {
                Symbol s = lookup(e.get("belief").asText(), "belief");
                slot = s.slot();
            }
            deps.add(slot);
            return Values.ref(slot);
        }
        if (e.has("call")) {
            return call(e, deps);
        }
        String op = e.path("op").asText("");
        return switch (op) {
            case "!" -> Values.not(value(e.get("arg"), deps));
            case "neg" -> Values.neg(value(e.get("arg"), deps));
            case "?:" -> Values.cond(value(e.get("cond"), deps), value(e.get("then"), deps), value(e.get("else"), deps));
            case "&", "|", "=", "!=", "<", ">", "<=", ">=", "+", "-", "*", "/" ->
                Values.binary(op, value(e.get("left"), deps), value(e.get("right"), deps));
            case "and", "or", "->", "not", "once", "while", "repeat", "range" ->
                throw error("roqme-expr", "the pattern operator '" + op + "' cannot be used as a value");
            default -> throw error("roqme-expr", "unsupported expression " + e);
        };
    }

    private ValueNode call(JsonNode e, TreeSet<Integer> deps) throws ModelException {
        String fn = e.get("call").asText();
        List<JsonNode> args = new ArrayList<>();
        e.path("args").forEach(args::add);
        boolean windowFn = List.of("avg", "min", "max", "count", "sum", "increasing", "decreasing", "stable").contains(fn);
        if (windowFn && args.size() == 2 || fn.equals("period")) {
            return window(fn, args, deps);
        }
        if (windowFn && args.size() == 1 && "event".equals(typeOf(args.get(0)))) {
            throw error("roqme-expr", fn + " of an event needs a window");
        }
        if (fn.equals("eventWhen") || fn.equals("update")) {
            throw error("roqme-expr", fn + "(...) is a pattern, not a value");
        }
        List<ValueNode> vs = new ArrayList<>();
        for (JsonNode a : args) {
            vs.add(value(a, deps));
        }
        int arity = switch (fn) {
            case "pow", "at", "includes" -> 2;
            default -> 1;
        };
        ValueNode f = vs.size() == arity ? Values.function(fn, vs) : null;
        if (f == null) {
            throw error("roqme-expr", "unsupported call " + fn + " with " + vs.size() + " argument(s)");
        }
        return f;
    }

    /** A window function: a new computed slot sampling its first argument. */
    private ValueNode window(String fn, List<JsonNode> args, TreeSet<Integer> deps) throws ModelException {
        if (args.isEmpty()) {
            throw error("roqme-expr", fn + " needs an argument");
        }
        int samples = 0;
        long ms = 0;
        if (fn.equals("period")) {
            samples = 2;
        } else {
            JsonNode w = args.get(1);
            if (w.has("time")) {
                ms = w.get("time").asLong();
            } else if (w.has("number")) {
                samples = w.get("number").asInt();
            } else {
                throw error("roqme-expr", fn + ": the window must be a time or a sample count literal");
            }
            if (ms <= 0 && samples <= 0) {
                throw error("roqme-expr", fn + ": the window must be positive");
            }
        }
        TreeSet<Integer> own = new TreeSet<>();
        JsonNode src = args.get(0);
        boolean event = "event".equals(typeOf(src)) || fn.equals("period");
        EventNode ev = event ? update(src, own) : null;
        ValueNode v = event ? null : value(src, own);
        int slot = slots++;
        atBySlot.put(slot, at);
        Window win = new Window(windows.size(), slot, v, ev, ints(own), fn.equals("period") ? null : Aggregate.of(fn), samples, ms);
        windows.add(win);
        computedBySlot.put(slot, new Computed(slot, null, win, ints(own)));
        deps.add(slot);
        return Values.ref(slot);
    }

    private String typeOf(JsonNode e) {
        return TypeOf.of(e, symbols);
    }

    private ModelException error(String code, String message) {
        return new ModelException(at == null ? String.valueOf(model.source()) : at, code, message);
    }

    static int[] ints(TreeSet<Integer> s) {
        return s.stream().mapToInt(Integer::intValue).toArray();
    }
}
