package org.miron.runtime.bus;

/** Bus topic names shared by the engine, the player and the tests. */
public final class Topics {
    public static final String ESTIMATE = "roqme.estimate";
    public static final String CONTEXT = "roqme.context";
    public static final String VARIANT_PREFIX = "miron.variant.";
    public static final String BLACKBOARD_PREFIX = "miron.blackboard.";
    public static final String OVERRIDE_PREFIX = "miron.override.";
    public static final String DECISION = "miron.decision";
    public static final String STATUS = "miron.status";

    private Topics() {
    }
}
