package org.miron.executor.decorators;

import org.miron.executor.Blackboard;
import org.miron.executor.DecoratorNode;
import org.miron.executor.Node;
import org.miron.executor.NodeInfo;
import org.miron.executor.NodeStatus;

/**
 * SubTree / SubTreePlus: runs the referenced tree's root, on the blackboard the builder prepared
 * for it (isolated with remappings, or the parent's when shared), and returns its status.
 */
public class SubTreeNode extends DecoratorNode {
    private final String treeId;
    private final Blackboard blackboard;

    public SubTreeNode(NodeInfo info, String treeId, Blackboard blackboard, Node root) {
        super(info, root);
        this.treeId = treeId;
        this.blackboard = blackboard;
    }

    @Override
    protected NodeStatus tick() {
        setStatus(NodeStatus.RUNNING);
        NodeStatus childStatus = child.executeTick();
        if (childStatus.isCompleted()) {
            resetChild();
        }
        return childStatus;
    }

    public String treeId() {
        return treeId;
    }

    /** The blackboard the subtree's nodes use. */
    public Blackboard blackboard() {
        return blackboard;
    }
}
