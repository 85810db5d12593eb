package org.miron.generator;

/**
 * How the objective weighs the utility of each property p (metric_p in [0,1] is the latest
 * RoQME estimate).
 */
public enum WeightPolicy {
    /** weight_p = 1 - metric_p: the least fulfilled property matters most (default). */
    NEED,
    /** weight_p = metric_p: the original MIRoN tools' choice. */
    METRIC;

    public String id() {
        return name().toLowerCase();
    }

    /** The policy named on the command line ("need", "metric"), or null. */
    public static WeightPolicy of(String id) {
        for (WeightPolicy policy : values()) {
            if (policy.id().equals(id)) {
                return policy;
            }
        }
        return null;
    }
}
