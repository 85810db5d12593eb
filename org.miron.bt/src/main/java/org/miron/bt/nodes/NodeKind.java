package org.miron.bt.nodes;

/** BehaviorTree.CPP's NodeType, named as the elements of its {@code <TreeNodesModel>}. */
public enum NodeKind {
    ACTION("Action"), CONDITION("Condition"), CONTROL("Control"), DECORATOR("Decorator"), SUBTREE("SubTree");

    private final String xmlName;

    NodeKind(String xmlName) {
        this.xmlName = xmlName;
    }

    /** The element that declares a node of this kind in a TreeNodesModel, e.g. {@code Decorator}. */
    public String xmlName() {
        return xmlName;
    }
}
