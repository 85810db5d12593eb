package org.miron.executor.skills;

import org.miron.executor.BtBuildException;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;

/**
 * {@code <Action ID="VariantAction" varpoint="task" value="{task_sel}"/>}: on every tick writes the
 * current decision for its variation point to its {@code value} port, so a Switch reading
 * {@code {task_sel}} follows the adaptation engine, and stays RUNNING (it monitors, it never
 * finishes). Before the first decision arrives it writes nothing and the Switch takes its default.
 */
public class VariantActionNode extends Node {
    private final VariantSource variants;
    private final String varpoint;

    public VariantActionNode(NodeInfo info, VariantSource variants) {
        super(info);
        this.variants = variants;
        this.varpoint = info.ports().raw("varpoint");
        if (varpoint == null || varpoint.isBlank()) {
            throw new BtBuildException(info.path() + ": VariantAction needs a varpoint attribute");
        }
        if (!info.ports().has("value")) {
            throw new BtBuildException(info.path() + ": VariantAction needs a value port, e.g. value=\"{" + varpoint + "_sel}\"");
        }
    }

    @Override
    protected NodeStatus tick() {
        variants.current(varpoint).ifPresent(value -> ports().set("value", value));
        return NodeStatus.RUNNING;
    }

    public String varpoint() {
        return varpoint;
    }
}
