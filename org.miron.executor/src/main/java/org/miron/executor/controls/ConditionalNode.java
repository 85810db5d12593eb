package org.miron.executor.controls;

import java.util.List;
import org.miron.executor.BtBuildException;
import org.miron.executor.ControlNode;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;

/** IfThenElse and WhileDoElse: a condition child, a then-branch and an optional else-branch. */
public abstract class ConditionalNode extends ControlNode {
    protected static final int CONDITION = 0;
    protected static final int THEN = 1;
    protected static final int ELSE = 2;

    protected ConditionalNode(NodeInfo info, List<Node> children, String kind) {
        super(info, children);
        if (children.size() != 2 && children.size() != 3) {
            throw new BtBuildException(info.path() + ": " + kind + " needs 2 or 3 children (condition, then, optional else), not "
                    + children.size());
        }
    }

    protected final boolean hasElse() {
        return children.size() == 3;
    }
}
