package org.miron.runtime.bus;

/** Bus topic names shared by the engine, the player and the tests. */
public final class Topics {
    public static final String ESTIMATE = "roqme.estimate";
    public static final String CONTEXT = "roqme.context";
    /** The RoQME provider's fired observations and its status (docs/wire-formats.md). */
    public static final String OBSERVATION = "roqme.observation";
    public static final String ROQME_STATUS = "roqme.status";
    public static final String VARIANT_PREFIX = "miron.variant.";
    public static final String BLACKBOARD_PREFIX = "miron.blackboard.";
    public static final String OVERRIDE_PREFIX = "miron.override.";
    public static final String DECISION = "miron.decision";
    public static final String STATUS = "miron.status";
    /** The BT executor: every node status change, and the tree it runs (docs/wire-formats.md). */
    public static final String BT_STATUS = "miron.bt.status";
    public static final String BT_TREE = "miron.bt.tree";
    /** The live requirement monitors (LiveRequirements): each violation and met-again, and their status. */
    public static final String REQUIREMENT = "miron.requirement";
    public static final String REQUIREMENT_STATUS = "miron.requirement.status";
    /** The broker's own topics: its hello (with its epoch) and the replies to sync subscriptions. */
    public static final String BROKER_PREFIX = "miron.broker.";
    public static final String BROKER_HELLO = "miron.broker.hello";
    public static final String BROKER_SYNC_PREFIX = "miron.broker.sync.";

    private Topics() {
    }
}
