package org.miron.diagram;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Which branch of each Switch runs for given blackboard values: BehaviorTree.CPP's SwitchN runs
 * the child of the first {@code case_k} equal to its {@code variable}, else its last child. The
 * woven tree switches its variants this way, so with the engine's decisions this shows the active
 * variant: the running branch gets {@code active}, the others {@code inactive}, as extra classes
 * for {@link SvgWriter#write(org.eclipse.sprotty.SGraph, Map)}.
 */
public final class VariantHighlight {
    private static final Pattern SWITCH = Pattern.compile("Switch\\d");
    private static final Pattern KEY = Pattern.compile("\\{([^{}]+)}");

    private VariantHighlight() {
    }

    /** Extra classes by node id, for blackboard {@code values} (key without braces → value). */
    public static Map<String, List<String>> classes(Diagram diagram, Map<String, String> values) {
        Map<String, List<String>> classes = new HashMap<>();
        for (Shape shape : diagram.shapes()) {
            if (!isSwitch(shape) || shape.children().isEmpty()) {
                continue;
            }
            String variable = port(shape, "variable");
            Matcher key = variable == null ? null : KEY.matcher(variable);
            if (key == null || !key.matches() || !values.containsKey(key.group(1))) {
                continue;
            }
            int active = activeChild(shape, values.get(key.group(1)));
            for (int i = 0; i < shape.children().size(); i++) {
                Shape child = shape.children().get(i);
                if (i == active) {
                    classes.computeIfAbsent(child.id(), k -> new ArrayList<>()).add("active");
                } else {
                    child.all().forEach(s -> classes.computeIfAbsent(s.id(), k -> new ArrayList<>()).add("inactive"));
                }
            }
        }
        return classes;
    }

    /** A Switch of a diagram: its node, the blackboard key it reads, its cases in order and its children's ids. */
    public record SwitchNode(String node, String key, List<String> cases, List<String> children) {
    }

    /** Every Switch reading a blackboard key, for pages that highlight the running branch themselves. */
    public static List<SwitchNode> switches(Diagram diagram) {
        List<SwitchNode> result = new ArrayList<>();
        for (Shape shape : diagram.shapes()) {
            String variable = isSwitch(shape) ? port(shape, "variable") : null;
            Matcher key = variable == null ? null : KEY.matcher(variable);
            if (key != null && key.matches() && !shape.children().isEmpty()) {
                List<String> cases = new ArrayList<>();
                for (int k = 1; k < shape.children().size(); k++) {
                    cases.add(port(shape, "case_" + k));
                }
                result.add(new SwitchNode(shape.id(), key.group(1), cases, shape.children().stream().map(Shape::id).toList()));
            }
        }
        return result;
    }

    private static boolean isSwitch(Shape shape) {
        return SWITCH.matcher(shape.title()).matches() || SWITCH.matcher(shape.type()).matches();
    }

    /** The index of the child that runs: the first matching case, else the default (last child). */
    static int activeChild(Shape shape, String value) {
        for (int k = 1; k < shape.children().size(); k++) {
            if (value.equals(port(shape, "case_" + k))) {
                return k - 1;
            }
        }
        return shape.children().size() - 1;
    }

    private static String port(Shape shape, String name) {
        return shape.ports().stream().filter(p -> p.name().equals(name)).map(Shape.Port::value).findFirst().orElse(null);
    }
}
