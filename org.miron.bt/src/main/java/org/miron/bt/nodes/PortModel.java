package org.miron.bt.nodes;

import java.util.List;
import java.util.Set;

/**
 * One port of a built-in, as its providedPorts() declares it: name, direction, type, default and
 * description. {@code required}: loading or the first tick fails without it (BehaviorTree.CPP
 * throws "missing port"); {@code minimum}: the smallest literal it accepts (-1 = forever for
 * num_cycles); {@code values}: the fixed set a literal is one of (empty: any); {@code versions}:
 * the BehaviorTree.CPP versions whose node has this port (Parallel's thresholds were renamed).
 * Instances are made by the factories and withers below, so a table entry reads as one line.
 */
public record PortModel(String name, PortDirection direction, PortType type, boolean required, String defaultValue,
        int minimum, List<String> values, String description, Set<Integer> versions) {

    public PortModel {
        values = List.copyOf(values);
        versions = Set.copyOf(versions);
    }

    public static PortModel input(String name, PortType type, String description) {
        // An unsigned port takes no negative literal: BT.CPP's convertFromString<unsigned> rejects it.
        return new PortModel(name, PortDirection.INPUT, type, false, null,
                type == PortType.UNSIGNED ? 0 : Integer.MIN_VALUE, List.of(), description, NodeCatalogue.BOTH);
    }

    public static PortModel output(String name, PortType type, String description) {
        return input(name, type, description).withDirection(PortDirection.OUTPUT);
    }

    public static PortModel inout(String name, PortType type, String description) {
        return input(name, type, description).withDirection(PortDirection.INOUT);
    }

    private PortModel withDirection(PortDirection to) {
        return new PortModel(name, to, type, required, defaultValue, minimum, values, description, versions);
    }

    /** The same port, required (no default). */
    public PortModel mandatory() {
        return new PortModel(name, direction, type, true, null, minimum, values, description, versions);
    }

    public PortModel withDefault(String value) {
        return new PortModel(name, direction, type, false, value, minimum, values, description, versions);
    }

    public PortModel atLeast(int min) {
        return new PortModel(name, direction, type, required, defaultValue, min, values, description, versions);
    }

    public PortModel oneOf(String... fixed) {
        return new PortModel(name, direction, type, required, defaultValue, minimum, List.of(fixed), description,
                versions);
    }

    /** The same port, in one BehaviorTree.CPP version only. */
    public PortModel onlyIn(int version) {
        return new PortModel(name, direction, type, required, defaultValue, minimum, values, description,
                Set.of(version));
    }

    public boolean isIn(int version) {
        return versions.contains(version);
    }

    /** The fixed values a literal takes: {@link #values}, else true/false for a boolean port. */
    public List<String> proposals() {
        return !values.isEmpty() ? values : type == PortType.BOOL ? List.of("true", "false") : List.of();
    }

    /** Whether a literal is one this port accepts: its type converts it, it is in range and among the values. */
    public boolean accepts(String literal) {
        if (!type.accepts(literal) || (!values.isEmpty() && !values.contains(literal.trim()))) {
            return false;
        }
        return !type.isInteger() || Integer.parseInt(literal.trim()) >= minimum;
    }
}
