package org.miron.bt.nodes;

/** BehaviorTree.CPP's PortDirection, named as the elements of its {@code <TreeNodesModel>}. */
public enum PortDirection {
    INPUT("input_port"), OUTPUT("output_port"), INOUT("inout_port");

    private final String xmlName;

    PortDirection(String xmlName) {
        this.xmlName = xmlName;
    }

    /** {@code input_port}, {@code output_port} or {@code inout_port}. */
    public String xmlName() {
        return xmlName;
    }
}
