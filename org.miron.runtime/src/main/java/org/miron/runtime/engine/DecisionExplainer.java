package org.miron.runtime.engine;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.miron.runtime.Json;

/**
 * Says why, in the model's names: the rules that applied with the values of their conditions'
 * inputs, and per changed varpoint what chose its value: the override, the rules that leave it no
 * other value, or the impacts that made it best against the runner-up (the best other value the
 * applied rules allow), in impact steps ({@code ++} against neutral is +2).
 */
final class DecisionExplainer {
    private static final double STEP = 100.0 / 6;

    private final IoModel io;
    private final RuleActivity activity;
    private final NativeModel m;
    /** Per rule: the slots its condition reads, in order. */
    private final int[][] conditionInputs;
    private final Map<Integer, InputSpec> inputBySlot = new HashMap<>();

    DecisionExplainer(IoModel io, RuleActivity activity) {
        this.io = io;
        this.activity = activity;
        this.m = activity.m;
        Map<String, Integer> slotByName = new HashMap<>();
        for (int s = 0; s < m.paramNames.length; s++) {
            slotByName.put(m.paramNames[s], s);
        }
        for (InputSpec in : io.inputs()) {
            inputBySlot.put(slotByName.get(in.param()), in);
        }
        JsonNode rules = io.decision().path("rules");
        conditionInputs = new int[rules.size()][];
        for (int r = 0; r < rules.size(); r++) {
            Set<Integer> slots = new LinkedHashSet<>();
            params(rules.get(r).get("condition"), slotByName, slots);
            conditionInputs[r] = slots.stream().mapToInt(Integer::intValue).toArray();
        }
    }

    private static void params(JsonNode n, Map<String, Integer> slots, Set<Integer> into) {
        if (n == null) {
            return;
        }
        if (n.has("param") && slots.containsKey(n.get("param").asText())) {
            into.add(slots.get(n.get("param").asText()));
        }
        n.path("args").forEach(a -> params(a, slots, into));
    }

    /** The rules that applied: {@code [{"rule": name, "inputs": {input: value}}]}, in priority order. */
    ArrayNode applied(RuleActivity.Activity a) {
        ArrayNode list = Json.MAPPER.createArrayNode();
        for (int r = 0; r < a.holds().length; r++) {
            if (a.holds()[r]) {
                ObjectNode rule = list.addObject();
                rule.put("rule", m.ruleNames[r]);
                ObjectNode inputs = rule.putObject("inputs");
                for (int slot : conditionInputs[r]) {
                    InputSpec in = inputBySlot.get(slot);
                    inputs.set(in.name(), value(in, activity.param[slot]));
                }
            }
        }
        return list;
    }

    /** Why varpoint v has its value: {@code {"because": text, "rules": [...], "runnerUp": value, "impacts": {p: steps}}}. */
    ObjectNode explain(RuleActivity.Activity a, int v) {
        ObjectNode why = Json.object();
        VariationPoint vp = io.varpoints().get(v);
        if (activity.overridden(v)) {
            why.put("because", "override");
            return why;
        }
        int chosen = activity.assign[v];
        boolean[] allowed = new boolean[m.sizes[v]];
        Set<Integer> restricting = new LinkedHashSet<>();
        int count = 0;
        for (int i = 0; i < allowed.length; i++) {
            activity.assign[v] = i;
            allowed[i] = true;
            for (NativeModel.Constraint k : m.constraints) {
                if (a.holds()[k.rule()] && a.kept()[k.rule()] && contains(k.overrides(), v)
                        && !m.pool.holds(k.body(), activity.param, activity.assign)) {
                    allowed[i] = false;
                    restricting.add(k.rule());
                }
            }
            count += allowed[i] ? 1 : 0;
        }
        activity.assign[v] = chosen;
        List<String> ruleTexts = new ArrayList<>();
        ArrayNode rules = why.putArray("rules");
        for (int r : restricting) {
            rules.add(m.ruleNames[r]);
            ruleTexts.add("rule " + m.ruleNames[r] + inputsText(r));
        }
        String byRules = String.join(", ", ruleTexts);
        int runnerUp = -1;
        double best = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < allowed.length; i++) {
            if (allowed[i] && i != chosen && gain(v, i) > best) {
                best = gain(v, i);
                runnerUp = i;
            }
        }
        if (count <= 1 || m.utilityMetric[v].length == 0 || runnerUp < 0) {
            why.put("because", !byRules.isEmpty() ? byRules
                    : count <= 1 ? "no other value"
                    : vp.preset() != null && vp.preset() == chosen ? "the preset: no rule or impact asks for another value"
                    : "kept: no rule or impact asks for another value");
            return why;
        }
        why.set("runnerUp", vp.values().get(runnerUp));
        ObjectNode impacts = why.putObject("impacts");
        List<String> parts = new ArrayList<>();
        List<String> costs = new ArrayList<>();
        for (int u = 0; u < m.utilityMetric[v].length; u++) {
            double steps = (m.utilityTable[v][u][chosen] - m.utilityTable[v][u][runnerUp]) / STEP;
            BigDecimal rounded = steps == 0 ? BigDecimal.ZERO : BigDecimal.valueOf(steps)
                    .round(new java.math.MathContext(Math.abs(steps) >= 1 ? 2 : 1, RoundingMode.HALF_UP))
                    .stripTrailingZeros(); // 2 significant digits, 1 below a step (neighbouring numbers)
            if (rounded.signum() != 0) {
                String name = inputBySlot.get(m.utilityMetric[v][u]).name();
                impacts.put(name, rounded);
                (rounded.signum() > 0 ? parts : costs).add(name + " " + (rounded.signum() > 0 ? "+" : "")
                        + rounded.toPlainString());
            }
        }
        String runner = vp.values().get(runnerUp).asText();
        String text = parts.isEmpty() ? "as good as " + runner + " for the weights now, kept"
                : "best for " + String.join(", ", parts) + " vs " + runner
                        + (costs.isEmpty() ? "" : " (" + String.join(", ", costs) + ")");
        why.put("because", byRules.isEmpty() ? text : text + " (within " + byRules + ")");
        return why;
    }

    private double gain(int v, int i) {
        double sum = 0;
        for (int u = 0; u < m.utilityMetric[v].length; u++) {
            double metric = activity.param[m.utilityMetric[v][u]];
            sum += (m.weightIsNeed ? 1 - metric : metric) * m.utilityTable[v][u][i];
        }
        return sum;
    }

    private String inputsText(int rule) {
        List<String> parts = new ArrayList<>();
        for (int slot : conditionInputs[rule]) {
            InputSpec in = inputBySlot.get(slot);
            JsonNode v = value(in, activity.param[slot]);
            // A metric reads as people say it (0.16), not as a double prints (0.15683722074396464).
            parts.add(in.name() + " = " + (v.isFloatingPointNumber()
                    ? BigDecimal.valueOf(v.asDouble()).round(new java.math.MathContext(2)).stripTrailingZeros().toPlainString()
                    : v.asText()));
        }
        return parts.isEmpty() ? "" : " (" + String.join(", ", parts) + ")";
    }

    /** An input's value as RoQME says it: a literal name, a Boolean, or a number. */
    private static JsonNode value(InputSpec in, double x) {
        if (!in.isMetric() && "int".equals(in.type()) && x >= 0 && x < in.literals().size()) {
            return Json.MAPPER.getNodeFactory().textNode(in.literals().get((int) x));
        }
        if (!in.isMetric() && "bool".equals(in.type())) {
            return Json.MAPPER.getNodeFactory().booleanNode(x == 1);
        }
        return Json.MAPPER.getNodeFactory().numberNode(x);
    }

    private static boolean contains(int[] a, int x) {
        for (int y : a) {
            if (y == x) {
                return true;
            }
        }
        return false;
    }
}
