package org.miron.executor;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.Function;
import java.util.function.Predicate;

/**
 * The ports of one node: its XML attributes read through its blackboard. A value {@code {key}} or
 * {@code ${key}} points at blackboard entry {@code key}, {@code =} at the entry named like the
 * port, anything else is a literal converted when read (BehaviorTree.CPP 3 getInput/setOutput).
 */
public final class Ports {
    private final String owner;
    private final Map<String, String> attributes;
    private final Blackboard blackboard;

    public Ports(Map<String, String> attributes, Blackboard blackboard) {
        this("", attributes, blackboard);
    }

    /** @param owner the node's path, named in error messages */
    public Ports(String owner, Map<String, String> attributes, Blackboard blackboard) {
        this.owner = owner;
        this.attributes = Collections.unmodifiableMap(new LinkedHashMap<>(attributes));
        this.blackboard = blackboard;
    }

    /** The blackboard key a port value points at, or empty when the value is a literal. */
    public static Optional<String> blackboardKey(String port, String value) {
        if (value == null) {
            return Optional.empty();
        }
        if (value.equals("=") || value.equals("{=}")) {
            return Optional.of(port); // "{=}": the version-4 spelling
        }
        int n = value.length();
        if (n >= 3 && value.charAt(0) == '{' && value.charAt(n - 1) == '}') {
            return Optional.of(value.substring(1, n - 1));
        }
        if (n >= 4 && value.startsWith("${") && value.charAt(n - 1) == '}') {
            return Optional.of(value.substring(2, n - 1));
        }
        return Optional.empty();
    }

    public Map<String, String> attributes() {
        return attributes;
    }

    /**
     * Binds a subtree call's ports into the subtree's own blackboard, as both BehaviorTree.CPP
     * versions do: a port pointing at a parent key is remapped to it, a literal is written into the
     * child. Attributes {@code skip} names (the call's own settings) are left out.
     *
     * @return the ports bound
     */
    public Set<String> bindInto(Blackboard child, Predicate<String> skip) {
        Set<String> bound = new LinkedHashSet<>();
        attributes.forEach((port, value) -> {
            if (skip.test(port)) {
                return;
            }
            Optional<String> key = blackboardKey(port, value);
            if (key.isPresent()) {
                child.remap(port, key.get(), madeBy(port));
            } else {
                child.set(port, value);
            }
            bound.add(port);
        });
        return bound;
    }

    public Blackboard blackboard() {
        return blackboard;
    }

    /** The attribute as written, or null. */
    public String raw(String port) {
        return attributes.get(port);
    }

    public boolean has(String port) {
        return attributes.containsKey(port);
    }

    /** The port's value: the literal, or the blackboard entry it points at; empty if either is missing. */
    public Optional<Object> get(String port) {
        String value = attributes.get(port);
        if (value == null) {
            return Optional.empty();
        }
        Optional<String> key = blackboardKey(port, value);
        if (key.isPresent()) {
            return blackboard.get(key.get());
        }
        return Optional.of(value);
    }

    public Optional<String> getString(String port) {
        return get(port).map(Conversions::toStringValue);
    }

    public Optional<Integer> getInt(String port) {
        return convert(port, Conversions::toInt);
    }

    public Optional<Double> getDouble(String port) {
        return convert(port, Conversions::toDouble);
    }

    public Optional<Boolean> getBoolean(String port) {
        return convert(port, Conversions::toBoolean);
    }

    /** Like {@link #getInt} but a missing port is an error, as for BehaviorTree.CPP's required ports. */
    public int requireInt(String port) {
        return getInt(port).orElseThrow(() -> missing(port));
    }

    /** This node's port as written, {@code Main/travel (goal="{ward}")}: who made a remapping. */
    public String madeBy(String port) {
        return (owner.isEmpty() ? "" : owner + " ") + "(" + port + "=\"" + attributes.get(port) + "\")";
    }

    /**
     * The blackboard key the port points at when that entry has no value (what BehaviorTree.CPP's
     * getInput reports as "unable to find the key"); empty for a literal or a key with a value.
     */
    public Optional<String> unsetKey(String port) {
        Optional<String> key = blackboardKey(port, attributes.get(port));
        return key.filter(k -> blackboard.get(k).isEmpty());
    }

    /**
     * The error of a required port that cannot be read: missing, or pointing at an entry without
     * a value, named with where that value was expected to come from (one line).
     */
    public BtRuntimeException missing(String port) {
        return new BtRuntimeException(missingMessage(port));
    }

    /** The text of {@link #missing}: the node's path, then {@link #problem}. */
    public String missingMessage(String port) {
        return prefix() + problem(port);
    }

    /**
     * Why a port cannot be read, without the node's path: {@code missing port 'x'}, or {@code port
     * goal="{goal}" reads blackboard key 'goal', which has no value (...where it comes from...)}.
     */
    public String problem(String port) {
        String value = attributes.get(port);
        if (value == null) {
            return "missing port '" + port + "'";
        }
        String key = blackboardKey(port, value).orElse(value);
        return "port " + port + "=\"" + value + "\" reads blackboard key '" + key + "', which has no value ("
                + blackboard.whereFrom(key) + ")";
    }

    private String prefix() {
        return owner.isEmpty() ? "" : owner + ": ";
    }

    private <T> Optional<T> convert(String port, Function<Object, T> conversion) {
        Optional<Object> value = get(port);
        if (value.isEmpty()) {
            return Optional.empty();
        }
        try {
            return Optional.of(conversion.apply(value.get()));
        } catch (IllegalArgumentException | ArithmeticException e) {
            throw new BtRuntimeException(prefix() + "port '" + port + "': " + e.getMessage(), e);
        }
    }

    /**
     * Writes an output port: to the entry it points at, or, as BehaviorTree.CPP 3's setOutput does,
     * to the entry named by a plain value ({@code output_key="goal"} writes "goal"). Returns false
     * when the node has no such port.
     */
    public boolean set(String port, Object value) {
        String written = attributes.get(port);
        if (written == null) {
            return false;
        }
        blackboard.set(blackboardKey(port, written).orElse(written), value);
        return true;
    }
}
