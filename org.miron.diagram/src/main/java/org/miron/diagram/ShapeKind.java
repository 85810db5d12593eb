package org.miron.diagram;

import java.util.Locale;

/**
 * What a diagram node stands for, which decides its shape and colour: the node kinds of
 * BehaviorTree.CPP (built-in leaves apart from the application's actions and conditions), and the
 * variation points and variants a MIRoN model adds.
 */
public enum ShapeKind {
    CONTROL, DECORATOR, ACTION, CONDITION, SUBTREE,
    /** A built-in leaf: AlwaysSuccess, SetBlackboard, Script, Sleep... */
    BUILTIN,
    /** A variation point of a MIRoN model, hung below the node it is bound to. */
    VARPOINT,
    /** One value of a variation point: the tree it puts in place, or the preset. */
    VARIANT;

    /** The Sprotty model type: {@code node:control}, {@code node:subtree}... */
    public String type() {
        return "node:" + name().toLowerCase(Locale.ROOT);
    }

    /** The kind as people say it: control, decorator, action... */
    public String word() {
        return name().toLowerCase(Locale.ROOT);
    }
}
