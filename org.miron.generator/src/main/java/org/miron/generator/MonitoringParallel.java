package org.miron.generator;

import static org.miron.bt.nodes.BuiltinNodes.ID;
import static org.miron.bt.nodes.BuiltinNodes.NUM_CYCLES;

import java.util.List;
import java.util.Objects;

import org.eclipse.emf.ecore.util.EcoreUtil;
import org.miron.bt.bt.Action;
import org.miron.bt.bt.BTModel;
import org.miron.bt.bt.BehaviorTree;
import org.miron.bt.bt.Parallel;
import org.miron.bt.bt.Repeat;
import org.miron.bt.bt.TreeNode;

/**
 * Wraps the main tree's root once in the monitoring Parallel, whose Repeat ticks one VariantAction
 * per enum varpoint (docs/generators.md, "Monitoring").
 */
final class MonitoringParallel {
    private final WovenNodes nodes;
    private final List<GenerationError> errors;

    MonitoringParallel(WovenNodes nodes, List<GenerationError> errors) {
        this.nodes = nodes;
        this.errors = errors;
    }

    void wrap(BTModel out, List<SampledVariationPoint> varpoints, AdaptationModel m) {
        String mainName = out.getMain_tree_to_execute() != null ? out.getMain_tree_to_execute()
                : out.getTrees().isEmpty() ? null : out.getTrees().get(0).getName();
        BehaviorTree main = out.getTrees().stream().filter(t -> Objects.equals(t.getName(), mainName)).findFirst()
                .orElse(null);
        if (main == null || main.getNodes().isEmpty()) {
            errors.add(new GenerationError(m.model.getImports().isEmpty() ? null : m.model.getImports().get(0),
                    "cannot add the monitoring Parallel: the main tree '" + Objects.toString(mainName, "")
                            + "' is not in the imported file itself"));
            return;
        }
        List<TreeNode> actions = varpoints.stream().map(this::variantAction).toList();
        Repeat repeat = nodes.leaf(nodes.factory.createRepeat(), "Repeat");
        repeat.getAttributes().add(nodes.attribute("name", "monitoring_repeat"));
        repeat.getAttributes().add(nodes.attribute(nodes.port("Repeat", NUM_CYCLES), "-1")); // forever
        if (actions.size() == 1) {
            repeat.setNode(actions.get(0));
        } else {
            // VariantAction stays RUNNING (it monitors): a Sequence would only ever tick the first,
            // so several of them run side by side.
            Parallel all = parallel("monitoring_variants", actions.size());
            all.getNodes().addAll(actions);
            repeat.setNode(all);
        }
        Parallel parallel = parallel("monitoring_parallel", 1);
        TreeNode root = main.getNodes().get(0);
        EcoreUtil.replace(root, parallel);
        parallel.getNodes().add(repeat);
        parallel.getNodes().add(root);
    }

    private TreeNode variantAction(SampledVariationPoint vp) {
        Action action = nodes.leaf(nodes.factory.createAction(), "Action");
        action.getAttributes().add(nodes.attribute(nodes.port("Action", ID), "VariantAction"));
        action.getAttributes().add(nodes.attribute("varpoint", vp.name));
        action.getAttributes().add(nodes.attribute("value", "{" + vp.selection() + "}"));
        return action;
    }

    private Parallel parallel(String name, int successes) {
        Parallel parallel = nodes.leaf(nodes.factory.createParallel(), "Parallel");
        parallel.getAttributes().add(nodes.attribute("name", name));
        parallel.getAttributes().add(nodes.attribute(nodes.successCount(), String.valueOf(successes)));
        parallel.getAttributes().add(nodes.attribute(nodes.failureCount(), "1"));
        return parallel;
    }

    /** Adds VariantAction to the TreeNodesModel, for editors such as Groot. */
    static String declareVariantAction(String content) {
        int end = content.lastIndexOf("</TreeNodesModel>");
        if (end < 0 || content.contains("\"VariantAction\"")) {
            return content;
        }
        int lineStart = content.lastIndexOf("\n", end) + 1;
        String indent = content.substring(lineStart, end);
        String declaration = "<Action ID=\"VariantAction\"><input_port name=\"varpoint\"/><output_port name=\"value\"/></Action>";
        if (lineStart > 0 && indent.trim().isEmpty()) {
            return content.substring(0, lineStart) + indent + "  " + declaration + "\n" + content.substring(lineStart);
        }
        return content.substring(0, end) + declaration + content.substring(end);
    }
}
